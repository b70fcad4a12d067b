"""``python -m oilgap.studies.cli``: the same as the ``oilgap`` console script."""

import sys

from oilgap.studies.cli import main

sys.exit(main())
