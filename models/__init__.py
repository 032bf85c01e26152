"""The project model files (MJCF and URDF), shipped as package data."""
