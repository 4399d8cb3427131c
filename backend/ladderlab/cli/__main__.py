"""``python -m ladderlab.cli``: the same command as ``ladderlab``."""

import sys

from . import main

sys.exit(main())
