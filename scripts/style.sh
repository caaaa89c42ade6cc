#!/usr/bin/env bash
# The style check (scripts/test.sh runs it; run it locally before a push):
#   1. format: clang-format --dry-run --Werror (.clang-format) on the lines the last commit
#      added or changed in C and C++ files (git diff BASE HEAD, BASE = HEAD~1 by default;
#      deleted files skipped). The tree as a whole is not reformatted: only what a commit
#      touches, so editing a line does not oblige reformatting its whole file.
#   2. tidy: clang-tidy (.clang-tidy, warnings are errors) on the translation units that
#      reach lib/ and ports/: lib's header check, the C APIs, the host port and the
#      firmware's portable part, from a compile_commands.json of a configure-only build
#      dir (build/style; nothing is compiled).
#   scripts/style.sh [BASE] [--format-only | --tidy-only]
# Environment: HSTMON_STYLE_JOBS (parallel clang-tidy runs, default nproc).
# Exit status: 0 clean; 1 a format or tidy finding; 2 a missing tool or a failed configure.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
base="" do_format=1 do_tidy=1
while [ $# -gt 0 ]; do
  case "$1" in
    --format-only) do_tidy=0; shift ;;
    --tidy-only) do_format=0; shift ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    -*) echo "style.sh: unknown argument '$1'" >&2; exit 2 ;;
    *) base="$1"; shift ;;
  esac
done
for tool in clang-format clang-tidy python3 cmake; do
  command -v "$tool" >/dev/null || { echo "style.sh: '$tool' not found (bash scripts/install-deps.sh)" >&2; exit 2; }
done
status=0

if [ "$do_format" = 1 ]; then
  if [ -z "$base" ] && git rev-parse -q --verify HEAD~1 >/dev/null; then base=HEAD~1; fi
  files=()
  if [ -n "$base" ]; then
    while IFS= read -r f; do
      [ -f "$f" ] && files+=("$f")
    done < <(git diff --name-only --diff-filter=d "$base" HEAD -- '*.c' '*.h' '*.cc' '*.cpp' '*.hh' '*.hpp')
  fi
  echo "== format: ${#files[@]} C/C++ file(s) changed since ${base:-(no parent commit)}"
  for f in "${files[@]}"; do
    # The lines the commit added or changed (hunks of `git diff -U0`: +start,count).
    lines=()
    while IFS= read -r range; do lines+=("--lines=$range"); done < <(
      git diff -U0 "$base" HEAD -- "$f" |
        sed -n 's/^@@ -[0-9,]* +\([0-9]*\)\(,\([0-9]*\)\)\{0,1\} @@.*/\1 \3/p' |
        awk '{ n = ($2 == "") ? 1 : $2; if (n > 0) print $1 ":" $1 + n - 1 }')
    [ ${#lines[@]} -gt 0 ] || continue
    if ! clang-format --dry-run --Werror "${lines[@]}" "$f"; then
      echo "style.sh: format: $f (fix the changed lines: git clang-format $base)" >&2
      status=1
    fi
  done
fi

if [ "$do_tidy" = 1 ]; then
  build="$root/build/style"
  mkdir -p "$root/build"  # a fresh clone has none; the configure log sits beside the tree
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    -DHSTMON_BUILD_BENCH=OFF -DHSTMON_BUILD_PYTHON=OFF >"$build.configure.log" 2>&1 || {
    cat "$build.configure.log" >&2; exit 2; }
  # One compile command per source (a file built into several targets is checked once).
  mkdir -p "$build/tidy"
  python3 - "$root" "$build/compile_commands.json" "$build/tidy" <<'PY'
import json, os, sys
root, db, out = sys.argv[1], sys.argv[2], sys.argv[3]
prefixes = ("lib/src/", "ports/c_api/src/", "ports/host/src/", "ports/cortex_m4_mps2/portable/")
seen, keep = set(), []
for e in json.load(open(db)):
    rel = os.path.relpath(e["file"], root)
    if rel.startswith(prefixes) and rel.endswith(".cpp") and rel not in seen:
        seen.add(rel)
        keep.append(e)
json.dump(keep, open(os.path.join(out, "compile_commands.json"), "w"), indent=1)
open(os.path.join(out, "files.txt"), "w").write("".join(e["file"] + "\n" for e in keep))
PY
  n=$(wc -l <"$build/tidy/files.txt")
  jobs=${HSTMON_STYLE_JOBS:-$(nproc)}
  echo "== tidy: $n translation units, $jobs at a time"
  start=$SECONDS
  if ! xargs -P"$jobs" -n1 clang-tidy -p "$build/tidy" --quiet <"$build/tidy/files.txt" 2> >(grep -v " warnings\? generated\.$\|^Suppressed \|^Use -header-filter\|NOLINT\|^$" >&2); then
    echo "style.sh: tidy: findings above (fix, or NOLINT(check) with the reason)" >&2
    status=1
  fi
  echo "== tidy: $((SECONDS - start)) s"
fi
exit $status
