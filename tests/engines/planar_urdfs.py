"""Small URDFs with a ``planar`` joint (an off-centre COM, a full inertia, a turning child), for the engine tests."""

from __future__ import annotations

from pathlib import Path

INERTIA = '<inertia ixx="{0}" iyy="{1}" izz="{2}" ixy="{3}" ixz="{4}" iyz="{5}"/>'


def _link(name: str, mass: float, com: str, inertia: tuple[float, ...]) -> str:
    return (
        f'<link name="{name}"><inertial><origin xyz="{com}"/><mass value="{mass}"/>'
        + INERTIA.format(*inertia)
        + "</inertial></link>"
    )


def _joint(name: str, kind: str, parent: str, child: str, origin: str, axis: str) -> str:
    limit = '<limit lower="-2" upper="2" effort="1" velocity="1"/>' if kind in ("revolute", "prismatic") else ""
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>{origin}'
        f'<axis xyz="{axis}"/>{limit}</joint>'
    )


BASE = ("base", 2.0, "0.3 -0.2 0.1", (0.2, 0.25, 0.3, 0.01, 0.02, 0.03))  # off-centre COM, full inertia
ARM = ("arm", 0.5, "0.2 0.05 0", (0.01, 0.02, 0.03, 0.0, 0.0, 0.0))
POST = ("post", 1.5, "0 0 0.2", (0.05, 0.05, 0.02, 0.0, 0.0, 0.0))

#: name -> (links, joints, the links the planar joint carries).
MODELS = {
    "planar base, revolute child": (
        ["world", BASE, ARM],
        [
            ("slider", "planar", "world", "base", '<origin xyz="0.1 0.2 0.3"/>', "0 0 1"),
            ("elbow", "revolute", "base", "arm", '<origin xyz="0.4 0 0"/>', "0 1 0"),
        ],
        ("base", "arm"),
    ),
    "turned planar base, tilted continuous child": (
        ["world", BASE, ARM],
        [
            ("slider", "planar", "world", "base", '<origin xyz="0.1 0.2 0.3" rpy="0.3 0.2 0.1"/>', "0 0 1"),
            ("elbow", "continuous", "base", "arm", '<origin xyz="0.4 0.1 0"/>', "0 0.6 0.8"),
        ],
        ("base", "arm"),
    ),
    "planar joint after a revolute": (
        ["world", POST, BASE, ARM],
        [
            ("turn", "revolute", "world", "post", '<origin xyz="0 0 0.1"/>', "0 0 1"),
            ("slider", "planar", "post", "base", '<origin xyz="0 0.3 0.4" rpy="0 0 0.5"/>', "0 0 1"),
            ("elbow", "revolute", "base", "arm", '<origin xyz="0.4 0 0"/>', "1 0 0"),
        ],
        ("base", "arm"),
    ),
}


def write_planar(tmp_path: Path, name: str, axis: str | None = None) -> Path:
    """Write model ``name`` of :data:`MODELS` (its planar joint about ``axis`` when given) as robot.urdf."""
    links, joints, _ = MODELS[name]
    body = "".join('<link name="world"/>' if link == "world" else _link(*link) for link in links)
    body += "".join(_joint(*j[:5], axis if axis is not None and j[1] == "planar" else j[5]) for j in joints)
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="planar_robot">{body}</robot>')
    return path


def carried_mass(name: str) -> float:
    """The mass the planar joint carries, summed from the links written above (by hand, not by an engine)."""
    links, _, carried = MODELS[name]
    return sum(link[1] for link in links if link != "world" and link[0] in carried)
