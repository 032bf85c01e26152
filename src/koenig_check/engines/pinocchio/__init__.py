"""Pinocchio: the loader (URDF and MJCF parsers), the state map to canonical coordinates, the adapter."""
