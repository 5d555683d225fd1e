"""Unitree robots: Go2 over DDS, A1 over UDP, their conventions and their fakes.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["a1_driver", "a1_fake", "a1_udp_layout", "conventions", "firmware_timeout", "go2_cdr",
           "go2_dds_types", "go2_driver", "go2_fake", "peer"]
