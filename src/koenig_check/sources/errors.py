"""The one error of model sources: a model that cannot be found where it is said to live, before any work."""

from __future__ import annotations

from koenig_check.exceptions import KoenigCheckError


class ModelSourceError(KoenigCheckError, ValueError):
    """A model named by its source cannot be had: an extra is missing, a name is unknown, a download cannot happen.

    The message is one line naming the model as typed and what to do: the extra to install, the close names,
    or the cache variable to set.  Raised before any model is loaded (a usage error: exit status 2).
    """


def missing_extra(model: str, extra: str, package: str) -> ModelSourceError:
    """The error for a source whose optional dependency is not installed.

    Parameters
    ----------
    model : str
        The model as typed (``menagerie:unitree_g1``).
    extra : str
        The koenig-check extra that installs it (``menagerie``).
    package : str
        The distribution it needs (``mujoco-menagerie``).

    Returns
    -------
    ModelSourceError
    """
    return ModelSourceError(f"{model}: needs {package}, which is not installed: pip install 'koenig-check[{extra}]'")
