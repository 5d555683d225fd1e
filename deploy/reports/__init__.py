"""Plain-text reports: the tables benches, drills, claims and logs print (rich renders them)."""

__all__ = ["table"]
