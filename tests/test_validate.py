from __future__ import annotations

import time
from pathlib import Path

import pytest

import koenig_check.validate
from koenig_check.validate import MAX_DEPTH, ModelFileError, preflight

MODELS = Path(__file__).resolve().parents[1] / "models"

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
    monkeypatch.setattr(koenig_check.validate, "MAX_FILE_BYTES", 10)
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
