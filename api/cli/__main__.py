"""``python -m oilgap.cli``: the same as the ``oilgap`` console script."""

import sys

from oilgap.cli import main

sys.exit(main())
