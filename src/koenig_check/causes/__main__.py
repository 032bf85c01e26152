"""``python -m koenig_check.causes``: print the catalogue's documentation page (``docs/causes.md``)."""

from koenig_check.causes.listing import markdown

print(markdown(), end="")
