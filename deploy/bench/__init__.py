"""``porter bench``: NMPC, simulation, recorder, drivers, WBC tick and deploy benchmarks.

Each bench is its own module (``deploy.bench.nmpc``, ``.sim``, ``.recorder``, ``.drivers``,
``.wbc_tick``, ``.deploy_runs``, ``.obstacle_family``; ``.rti_fidelity`` serves the NMPC bench)
with its runner and ``format_table``; nothing is re-exported here, as the names are the same
in each.
"""

__all__: list[str] = []
