"""NumPy references of gait quantities that production code computes elsewhere."""

from __future__ import annotations

import numpy as np

from core.locomotion.gait import TROT_OFFSETS, TrotGait


def swing_progress(gait: TrotGait, time_s: float) -> np.ndarray:
    """(4,) fraction of the swing done at ``time_s`` for swing legs, 0 for stance legs."""
    phase = np.mod(time_s / gait.period_s + TROT_OFFSETS, 1.0)
    progress = (phase - gait.duty_factor) / (1.0 - gait.duty_factor)
    return np.where(phase < gait.duty_factor, 0.0, progress)
