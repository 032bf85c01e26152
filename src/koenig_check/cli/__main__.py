"""``python -m koenig_check.cli``: the command line, as the ``koenig-check`` console script."""

import sys

from koenig_check.cli.main import main

sys.exit(main())
