"""One plain-text table, laid out by rich: columns sized to their contents, numbers right-
aligned, a rule under the header, no colour or box characters (the text goes to terminals,
files and README alike), then notes below. Cells are strings: each caller formats its own
numbers (units and digits are part of what a report says)."""

from __future__ import annotations

import io
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

from rich import box
from rich.console import Console
from rich.table import Table
from rich.text import Text

__all__ = ["Column", "render_table"]

# rich's SIMPLE_HEAD with an ASCII rule: only a line of dashes under the header
_RULE_UNDER_HEADER = box.Box("    \n    \n -- \n    \n    \n    \n    \n    \n", ascii=True)


@dataclass(frozen=True)
class Column:
    """A column's header and alignment (``right`` for numbers)."""

    header: str
    justify: Literal["left", "right"] = "left"


def render_table(columns: Sequence[Column | str], rows: Sequence[Sequence[object]],
                 notes: Sequence[str] = ()) -> str:
    """``rows`` (one cell per column, ``None`` as empty) under ``columns`` (a bare string is
    a left-aligned column), as text lines; ``notes`` follow, one line each."""
    table = Table(box=_RULE_UNDER_HEADER, show_edge=False, pad_edge=False, padding=(0, 1),
                  header_style="", highlight=False)
    for column in columns:
        column = Column(column) if isinstance(column, str) else column
        # Text, not str: "[ms]" in a header or a cell is text, never rich markup
        table.add_column(Text(column.header), justify=column.justify, no_wrap=True)
    for row in rows:
        if len(row) != len(columns):
            raise ValueError(f"a row of {len(row)} cells under {len(columns)} columns")
        table.add_row(*(Text("" if cell is None else str(cell)) for cell in row))
    console = Console(file=io.StringIO(), width=10_000, color_system=None, force_terminal=False,
                      highlight=False, emoji=False, markup=False)
    console.print(table, crop=False)
    lines = [line.rstrip() for line in console.file.getvalue().splitlines()]  # type: ignore[attr-defined]
    return "\n".join([*[line for line in lines if line.strip() or not lines], *notes])
