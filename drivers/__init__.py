"""Everything that touches the world: driver interfaces, robot descriptions and the links."""
