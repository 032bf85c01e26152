"""Where model files come from besides a path: MuJoCo Menagerie, robot_descriptions and xacro files.

``menagerie:NAME[:ENTRY]`` (extra ``[menagerie]``), ``rd:NAME`` (extra ``[descriptions]``) and ``*.xacro``
(extra ``[xacro]``) become a local model file with a label saying where it came from
(:func:`koenig_check.sources.external.resolve_external`); :func:`koenig_check.sources.catalogue.resolve_model`
asks it first.
"""

from koenig_check.sources.errors import ModelSourceError
from koenig_check.sources.external import ExternalModel, is_external, prepare, resolve_external, source_label

__all__ = ["ExternalModel", "ModelSourceError", "is_external", "prepare", "resolve_external", "source_label"]
