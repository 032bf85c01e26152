"""Model files as written, apart from any engine.

The pre-flight check (:mod:`~koenig_check.modelfile.validate`) and the MJCF reader
(:mod:`~koenig_check.modelfile.mjcf`: includes, default classes, root bodies, frames).
"""
