"""porter's jobs: the control loop, safety, recording, viewing, the simulated world, benches, CLI."""
