#!/usr/bin/env bash
# Checks that C++ files are formatted as .clang-format says (clang-format --dry-run
# --Werror: each deviation is printed with its file and line, and the exit status is 1).
# With no argument: every C++ file of the repository; otherwise the files given (the
# pre-commit hook passes the staged ones).  To reformat instead of checking:
#     git ls-files -z '*.cpp' '*.hpp' '*.h' '*.cc' | xargs -0 clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."
# The tree is formatted by Debian's clang-format 14 (bookworm's `clang-format` package,
# installed by scripts/setup.sh); another major version formats some constructs differently.
want=14
if ! command -v clang-format >/dev/null 2>&1; then
  echo "check_format: clang-format not found (scripts/setup.sh installs Debian's clang-format $want)" >&2
  exit 2
fi
have=$(clang-format --version | sed -n 's/.*version \([0-9][0-9]*\).*/\1/p')
if [ "$have" != "$want" ]; then
  echo "check_format: clang-format $have found, the tree is formatted by clang-format $want: $(clang-format --version)" >&2
  exit 2
fi
if (($#)); then
  clang-format --dry-run --Werror "$@"
elif git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git ls-files -z '*.cpp' '*.hpp' '*.h' '*.cc' | xargs -0 clang-format --dry-run --Werror
else
  find . \( -path ./build -o -path ./.venv \) -prune -o \
    \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cc' \) -print0 |
    xargs -0 clang-format --dry-run --Werror
fi
