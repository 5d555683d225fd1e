"""porter's pure math: models, NMPC, locomotion, estimation and the SRB plant; no I/O."""
