"""koenig-check: cross-check rigid-body kinetic energy between MuJoCo, Pinocchio and a paper's formulas."""

from koenig_check.segments import SegmentStates

__all__ = ["SegmentStates"]
__version__ = "0.1.0"
