# Sourced by scripts/setup.sh and scripts/test.sh (and so by every C++ build they start:
# the binding, build/cpp, the wrong variant, the C++ mutants): compile through ccache when
# it is installed.  CMake reads CMAKE_<LANG>_COMPILER_LAUNCHER from the environment when it
# configures a new build tree.  CCACHE_BASEDIR and CCACHE_NOHASHDIR let a fresh clone in
# another folder reuse the objects of an earlier one (the debug info then names the folder
# of the first build).
if command -v ccache >/dev/null 2>&1; then
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR=1
fi
