"""python -m safestate.prove MODEL.tla ..."""

import sys

from .cli import main

sys.exit(main())
