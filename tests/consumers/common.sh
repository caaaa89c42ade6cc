# Sourced by the consumer test scripts. Environment (set by tests/consumers/CMakeLists.txt):
#   HSTMON_SRC      the repository root
#   HSTMON_PREFIX   where consumers.install put the package (cmake --install … --prefix)
#   CONSUMER_WORK   scratch root; each script gets CONSUMER_WORK/<name>, emptied first
#   CC, CXX         this build's compilers
#   LDFLAGS         this build's executable link flags (the sanitizer runtime in the
#                   ASan+UBSan build, whose libhstmon_c.a is instrumented)
set -euo pipefail
work="$CONSUMER_WORK/$(basename "$0" .sh)"
rm -rf "$work"
mkdir -p "$work"
jobs=2
