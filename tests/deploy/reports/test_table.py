"""Plain-text tables: columns sized to the widest cell, numbers right-aligned, brackets kept as
text (no rich markup), a rule of dashes under the header, notes after."""

from __future__ import annotations

import pytest

from deploy.reports.table import Column, render_table


def test_columns_align_and_text_stays_text() -> None:
    text = render_table(["fault", Column("detected [ms]", "right"), "detail"],
                        [["e-stop pressed", "4", "rejected {'crc': 50} [bold]x[/bold]"],
                         ["MoCap lost", "100", None]], ["1 of 2 noted"])
    header, rule, first, second, note = text.splitlines()
    assert header.split() == ["fault", "detected", "[ms]", "detail"]
    assert set(rule) == {"-"} and len(rule) >= len(first)
    # right-aligned numbers end in the same column, under the header's end
    end = header.index("[ms]") + len("[ms]")
    assert first[:end].endswith(" 4") and second[:end].endswith("100")
    assert first.endswith("rejected {'crc': 50} [bold]x[/bold]")  # markup is kept as text
    assert second.rstrip() == second and note == "1 of 2 noted"
    assert first.index("e-stop") == 0 and "\x1b" not in text  # no colour codes


def test_a_row_of_the_wrong_width_is_an_error() -> None:
    with pytest.raises(ValueError, match="2 cells under 3 columns"):
        render_table(["a", "b", "c"], [["1", "2"]])
