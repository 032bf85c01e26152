"""MuJoCo: the loader (MJCF or URDF through MuJoCo's compiler, inertia repair) and the adapter."""
