"""Mesh URIs resolved to files: ``package://`` in the package directories, ``file://``, relative paths."""

from __future__ import annotations

from koenig_check.sources.uris import resolve_uri


def test_resolve_uri(tmp_path):
    pkg = tmp_path / "share" / "my_pkg" / "meshes"
    pkg.mkdir(parents=True)
    mesh = pkg / "m.stl"
    mesh.write_text("solid")
    dirs = (tmp_path / "share",)
    assert resolve_uri("package://my_pkg/meshes/m.stl", tmp_path, dirs) == mesh
    assert resolve_uri("package:///my_pkg/meshes/m.stl", tmp_path, dirs) == mesh  # triple slash (talos)
    assert resolve_uri("package://my_pkg/meshes/missing.stl", tmp_path, dirs) is None
    assert resolve_uri(f"file://{mesh}", tmp_path, dirs) == mesh
    assert resolve_uri("share/my_pkg/meshes/m.stl", tmp_path, dirs) == mesh
