"""Links grouped into segments and lumped: the grouping, the massless segment's finding, and the parallel-axis sum
written by hand."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.engines.link_groups import group_links
from koenig_check.engines.specs import reference
from koenig_check.findings import Kind

#: Five links: 0 welded to the world, 1 and 3 moved by joints "a" and "b", 2 fixed to 1, 4 fixed to 3.
CARRIER = [-1, 1, 1, 3, 3]
NAME_OF = {1: "a", 3: "b"}


def test_links_fixed_to_a_head_join_its_segment_in_the_state_maps_order() -> None:
    mass = np.array([5.0, 1.0, 2.0, 3.0, 0.0])
    weighs = mass > 0
    groups = group_links(CARRIER, weighs, mass, NAME_OF, ["b", "a"])
    assert groups.names == ("b", "a")
    assert [list(m) for m in groups.members] == [[3], [1, 2]]  # link 4 weighs nothing: not a member
    assert list(groups.heads) == [3, 1]
    assert groups.findings("someengine") == []


def test_a_segment_whose_links_weigh_nothing_is_left_out_and_named_once() -> None:
    mass = np.array([5.0, 1.0, 2.0, 0.0, 0.0])
    inertia_only = np.array([False, True, True, True, False])  # link 3: a massless link with inertia counts
    groups = group_links(CARRIER, inertia_only, mass, NAME_OF, ["a", "b"])
    assert groups.names == ("a",) and groups.massless == ("b",)
    (finding,) = groups.findings(reference())
    assert finding.kind is Kind.SEGMENTS and finding.engine == reference() and finding.element == "segments b"


def test_lumped_mass_and_inertia_by_hand() -> None:
    """Links of 2 kg at the origin and 1 kg at x = 1, each diag(1, 2, 3) in world axes, head turned 90° about z.

    COM at x = 1/3; the parallel-axis terms about y and z are 2 (1/3)² + 1 (2/3)² = 2/3; in the head's frame (x
    and y swapped) the inertia is diag(4 + 2/3, 2, 6 + 2/3).
    """
    mass = np.array([2.0, 1.0])
    com = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    inertia = np.array([np.diag([1.0, 2.0, 3.0])] * 2)
    turned = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    rotation = np.array([turned, np.eye(3)])
    groups = group_links([0, 0], np.array([True, True]), mass, {0: "a"}, ["a"])
    seg_mass, seg_inertia = groups.lumped(mass, com, inertia, rotation)
    assert seg_mass == pytest.approx([3.0], abs=0)
    expected = np.diag([4.0 + 2.0 / 3.0, 2.0, 6.0 + 2.0 / 3.0])
    assert np.abs(seg_inertia[0] - expected).max() <= 8 * np.finfo(float).eps * np.abs(expected).max()


def test_mass_average_by_hand() -> None:
    mass = np.array([2.0, 1.0])
    groups = group_links([0, 0], np.array([True, True]), mass, {0: "a"}, ["a"])
    values = np.array([[[0.0, 3.0, 0.0], [3.0, 0.0, 6.0]]])  # one pose, two links
    assert np.abs(groups.mass_average(mass, values) - [[[1.0, 2.0, 2.0]]]).max() <= 4 * np.finfo(float).eps
