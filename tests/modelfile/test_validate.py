from __future__ import annotations

import time
from pathlib import Path

import pytest

import koenig_check.modelfile.validate
from koenig_check.modelfile.validate import MAX_DEPTH, ModelFileError, preflight

MODELS = Path(__file__).resolve().parents[2] / "models"

BILLION_LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
 <!ENTITY lol9 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
]>
<robot name="r"><link name="&lol9;"/></robot>
"""


@pytest.mark.parametrize("path", sorted(MODELS.glob("*.xml")) + sorted(MODELS.glob("*.urdf")), ids=lambda p: p.name)
def test_project_models_pass(path: Path) -> None:
    assert preflight(path) == ("mjcf" if path.suffix == ".xml" else "urdf")


@pytest.mark.parametrize(
    ("content", "message"),
    [
        ("", "file is empty"),
        ("not xml at all", "not well-formed XML at line 1"),
        ("<mujoco><worldbody><body name='a'>", "not well-formed XML"),
        ("<robot name='r'><link name='a'></robot>", "not well-formed XML at line 1"),
        (
            "<sdf version='1.6'><model/></sdf>",
            "root element <sdf> is neither <mujoco> (MJCF) nor <robot> (URDF)",
        ),
        (BILLION_LAUGHS, "line 2: DOCTYPE/ENTITY declarations are refused"),
        (
            "<robot>" + "<a>" * (MAX_DEPTH + 5) + "</a>" * (MAX_DEPTH + 5) + "</robot>",
            "nested deeper than 256",
        ),
    ],
    ids=["empty", "not-xml", "truncated-mjcf", "truncated-urdf", "sdf", "entity-bomb", "deep"],
)
def test_bad_files_get_one_line_errors_naming_the_file(tmp_path: Path, content: str, message: str) -> None:
    path = tmp_path / "bad.xml"
    path.write_text(content)
    start = time.perf_counter()
    with pytest.raises(ModelFileError) as info:
        preflight(path)
    assert time.perf_counter() - start < 5.0  # bounded: no expansion, no deep recursion
    text = str(info.value)
    assert message in text and str(path) in text and "\n" not in text


def test_missing_and_directory(tmp_path: Path) -> None:
    with pytest.raises(ModelFileError, match="file not found"):
        preflight(tmp_path / "nope.urdf")
    with pytest.raises(ModelFileError, match="is a directory"):
        preflight(tmp_path)


def test_unreadable(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "locked.urdf"
    path.write_text("<robot name='r'/>")

    def deny(self: Path) -> bytes:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(Path, "read_bytes", deny)
    with pytest.raises(ModelFileError, match=r"locked.urdf: cannot be read \(Permission denied\)"):
        preflight(path)


def test_oversized_file_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "big.urdf"
    path.write_text("<robot name='r'/>")  # 17 bytes
    assert preflight(path) == "urdf"
    monkeypatch.setattr(koenig_check.modelfile.validate, "MAX_FILE_BYTES", 10)
    with pytest.raises(ModelFileError) as info:
        preflight(path)
    text = str(info.value)
    assert "17 bytes, larger than the 10 bytes accepted" in text and str(path) in text and "\n" not in text


def test_nesting_depth_limit_is_exact(tmp_path: Path) -> None:
    path = tmp_path / "deep.urdf"
    inner = MAX_DEPTH - 1  # with the root, MAX_DEPTH levels: accepted
    path.write_text("<robot>" + "<a>" * inner + "</a>" * inner + "</robot>")
    assert preflight(path) == "urdf"
    path.write_text("<robot>" + "<a>" * (inner + 1) + "</a>" * (inner + 1) + "</robot>")
    with pytest.raises(ModelFileError, match=f"nested deeper than {MAX_DEPTH}"):
        preflight(path)


# What Expat refuses and both engines read (TinyXML2 skips white space before the declaration and stops at NUL).
_READ_BY_THE_ENGINES = {
    "blank-line-before-declaration": lambda text: b'\n<?xml version="1.0"?>\n' + text,
    "trailing-nul-byte": lambda text: b'<?xml version="1.0"?>\n' + text + b"\0",
}


@pytest.mark.parametrize("model", ["serial7.urdf", "gimbal.xml"])
@pytest.mark.parametrize("case", sorted(_READ_BY_THE_ENGINES))
def test_a_file_both_engines_read_is_not_refused_and_checks_like_the_original(
    tmp_path: Path, model: str, case: str
) -> None:
    import koenig_check
    from koenig_check.engines import load_model

    path = tmp_path / model
    path.write_bytes(_READ_BY_THE_ENGINES[case]((MODELS / model).read_bytes()))
    assert preflight(path) == ("urdf" if model.endswith(".urdf") else "mjcf")
    pair = load_model(path)
    original = load_model(MODELS / model)
    assert pair.mujoco.model.nv == original.mujoco.model.nv and pair.pinocchio.model.nv == original.pinocchio.model.nv
    check = koenig_check.compare([path], n_poses=5, seed=1)
    assert check.ok, check.reason()


@pytest.mark.parametrize(
    ("content", "where"),
    [
        (b"<robot name='r'><link name='a'>\0</link></robot>", "line 1"),  # a NUL inside: TinyXML2 stops there too
        (b"\n<robot name='r'><link name='a'></robot>", "line 2"),
        # MuJoCo (TinyXML2) names line 3, where <body> opens; Expat line 4, where </bdy> fails to close it
        (b"<mujoco>\n<worldbody>\n<body name='a'>\n</bdy>\n</worldbody>\n</mujoco>", "line 4"),
    ],
    ids=["nul-inside", "blank-line-then-truncated", "mismatched-tag-lines-apart"],
)
def test_malformed_xml_the_engines_refuse_too_is_one_line_with_mujocos_own_reason(
    tmp_path: Path, content: bytes, where: str
) -> None:
    import mujoco

    path = tmp_path / "bad.urdf"
    path.write_bytes(content)
    with pytest.raises(ModelFileError) as info:
        preflight(path)
    with pytest.raises(ValueError) as engine:
        mujoco.MjSpec.from_file(str(path))
    text = str(info.value)
    assert text.startswith(f"{path}: not well-formed XML at {where}") and "\n" not in text
    said = " ".join(str(engine.value).split())
    assert text.endswith(f"; MuJoCo: {said}")  # MuJoCo's own reason, whole: its line is where <body> opens
