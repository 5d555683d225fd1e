"""``python -m deploy.cli``: the ``porter`` command."""

import sys

from deploy.cli.porter import main

sys.exit(main())
