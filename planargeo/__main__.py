"""``python -m planargeo``: the same as the ``planargeo`` command."""
import sys

from planargeo.cli import main

sys.exit(main())
