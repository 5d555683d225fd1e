"""``porter paper table1``: the paper's Table I, distributed vs centralized NLP solve time for
2, 3 and 4 agents, under each controller profile: the paper's (its NLP, IPOPT to
convergence) and porter's (its NLP, rti), in closed loop on the SRB plant
(``deploy.bench.nmpc``)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from deploy.bench.nmpc import BenchRow, run_bench
from deploy.cli.conventions import OK, Output
from deploy.paper.reproduce import Profile, profile_documents
from deploy.reports.table import Column, render_table

# Table I of the paper: decision variables (dist., cent.), IPOPT iterations, distributed and
# centralized NLP solve time [ms] (average, standard deviation).
PAPER_TABLE1: dict[int, dict[str, Any]] = {
    2: {"variables": (408, 612), "iterations": 6, "distributed": (9.28, 0.27),
        "centralized": (7.62, 0.66)},
    3: {"variables": (456, 864), "iterations": 6, "distributed": (11.34, 0.97),
        "centralized": (12.46, 1.11)},
    4: {"variables": (504, 1116), "iterations": 5, "distributed": (11.55, 0.82),
        "centralized": (15.07, 0.95)},
}


def nlp_ms(row: BenchRow) -> dict[str, float]:
    """Time of one NLP solve: a local one (distributed) or the whole problem (centralized)."""
    return row.local_ms if row.local_ms is not None else row.update_ms


def table1_rows(runs: list[tuple[str, list[BenchRow]]]) -> list[dict]:
    """Per team size and profile (label, its bench rows): both modes' NLP time and the
    distributed reduction."""
    out = []
    agent_counts = sorted({r.agents for _, rows in runs for r in rows})
    for agents in agent_counts:
        for label, rows in runs:
            pair = {r.mode: r for r in rows if r.agents == agents}
            if set(pair) != {"distributed", "centralized"}:
                continue
            solver = pair["distributed"].solver
            dist, cent = nlp_ms(pair["distributed"]), nlp_ms(pair["centralized"])
            paper = PAPER_TABLE1.get(agents)
            row: dict[str, Any] = {"agents": agents, "profile": label, "solver": solver,
                   "variables": (pair["distributed"].variables, pair["centralized"].variables),
                   "distributed_ms": (dist["mean"], dist["std"]),
                   "centralized_ms": (cent["mean"], cent["std"]),
                   "reduction": 1.0 - dist["mean"] / cent["mean"],
                   # one ADMM update runs two rounds of local solves and the consensus: the
                   # whole update against the centralized one is the ratio a loop feels
                   "update_ms": (pair["distributed"].update_ms["mean"],
                                 pair["centralized"].update_ms["mean"]),
                   "update_ratio": (pair["distributed"].update_ms["mean"]
                                    / pair["centralized"].update_ms["mean"]),
                   "iterations": (pair["distributed"].iterations_mean,
                                  pair["centralized"].iterations_mean)}
            if paper is not None:
                row["paper"] = {**paper, "reduction": 1.0 - paper["distributed"][0]
                                / paper["centralized"][0]}
            out.append(row)
    return out


def format_table1(rows: list[dict]) -> str:
    cells = []
    for r in rows:
        paper = r.get("paper")
        cells.append([
            str(r["agents"]), r["profile"], r["solver"],
            f"{r['variables'][0]}/{r['variables'][1]}",
            f"{r['iterations'][0]:.1f}/{r['iterations'][1]:.1f}",
            f"{r['distributed_ms'][0]:.2f} ±{r['distributed_ms'][1]:.1f}",
            f"{r['centralized_ms'][0]:.2f} ±{r['centralized_ms'][1]:.1f}",
            f"{r['reduction']:+.0%}", f"{r['update_ratio']:.2f}",
            f"{paper['distributed'][0]:.2f} / {paper['centralized'][0]:.2f}, "
            f"{paper['reduction']:+.0%}" if paper else ""])
    columns: list[Column | str] = [Column("n", "right"), "profile", "solver",
               *(Column(name, "right") for name in ("vars d/c", "iters d/c", "dist ms",
                                                    "cent ms", "reduction",
                                                    "update d/c")),
               "paper (IPOPT): dist / cent ms, reduction"]
    return ("porter paper table1: distributed vs centralized NLP solve time (mean ± std)\n"
            + render_table(columns, cells, [
                "reduction = 1 - distributed / centralized NLP time; distributed = one local "
                "NLP (solved in parallel, one process per agent); update d/c = a whole "
                "distributed update (its ADMM iterations, local solves and consensus) over "
                "a whole centralized one"]))


def reproduce_table1(agent_counts: list[int], duration_s: float, out: Path, output: Output,
                     profiles: list[Profile]) -> int:
    runs = []
    for label, settings in profiles:
        rows, _, _ = run_bench(agent_counts, [settings.solver.name], duration_s,
                               parallel=True, include_reference=False,
                               base_settings=settings, with_checks=False)
        runs.append((label, rows))
    table = table1_rows(runs)
    output.report(format_table1(table))
    out.mkdir(parents=True, exist_ok=True)
    document = {"claim": "table1", "profiles": profile_documents(profiles), "rows": table,
                "bench_rows": {label: [r.as_dict() for r in rows] for label, rows in runs}}
    (out / "table1.json").write_text(json.dumps(document, indent=2) + "\n")
    output.progress(f"wrote {out / 'table1.json'}")
    output.write_json(document)
    return OK
