"""``porter bench``: NMPC, simulation, recorder, drivers and deploy benchmarks."""
