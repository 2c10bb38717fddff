"""``python -m veronte4x``: the same command line as the ``veronte4x`` script."""

import sys

from veronte4x.cli import main

sys.exit(main())
