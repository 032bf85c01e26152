"""Small URDF files written for a test: links, joints, and a base -> l1 -> l2 chain of revolute joints."""

from __future__ import annotations


def urdf_text(links: str, joints: str) -> str:
    return f'<robot name="t">{links}{joints}</robot>'


def urdf_link(name: str, mass: float | None = 1.0, inertia=(0.1, 0.2, 0.25, 0.0, 0.0, 0.0), extra: str = "") -> str:
    if mass is None:
        return f'<link name="{name}">{extra}</link>'
    ixx, iyy, izz, ixy, ixz, iyz = inertia
    return (
        f'<link name="{name}"><inertial><origin xyz="0.05 0.02 0.01"/><mass value="{mass}"/>'
        f'<inertia ixx="{ixx}" iyy="{iyy}" izz="{izz}" ixy="{ixy}" ixz="{ixz}" iyz="{iyz}"/></inertial>{extra}</link>'
    )


def urdf_joint(name: str, parent: str, child: str, kind: str = "revolute", xyz: str = "0 0 0.3") -> str:
    limit = '<limit lower="-2" upper="2" effort="1" velocity="1"/>' if kind == "revolute" else ""
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin xyz="{xyz}" rpy="0.1 0 0.2"/><axis xyz="0 1 0"/>{limit}</joint>'
    )


def write_model(tmp_path, text: str, name: str = "robot.urdf"):
    path = tmp_path / name
    path.write_text(text)
    return path


def urdf_chain(tmp_path, l2: str, extra_links: str = "", extra_joints: str = ""):
    text = urdf_text(
        urdf_link("base") + urdf_link("l1") + l2 + extra_links,
        urdf_joint("j1", "base", "l1") + urdf_joint("j2", "l1", "l2") + extra_joints,
    )
    return write_model(tmp_path, text)
