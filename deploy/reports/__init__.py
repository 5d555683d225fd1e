"""Plain-text reports: the tables benches, drills, claims and logs print (rich renders them)."""

from deploy.reports.table import Column, render_table

__all__ = ["Column", "render_table"]
