"""``python -m safestate.conform`` = ``safestate conform``."""

import argparse
import sys

from .cli import add_arguments, run

if __name__ == "__main__":
    parser = argparse.ArgumentParser(prog="safestate conform", description=__doc__)
    add_arguments(parser)
    sys.exit(run(parser.parse_args()))
