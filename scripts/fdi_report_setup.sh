# Sourced by the scripts that regenerate a docs/ page from the shipped circuits with
# hstmon-fdi (circuit_tcg_report.sh, isolability_report.sh): sets root (the source tree)
# and bin, the hstmon-fdi of BUILD_DIR $1 (default build/host-release); exits 2, naming
# the calling script, when it is not built.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${1:-$root/build/host-release}/bin/hstmon-fdi"
[ -x "$bin" ] || { echo "$(basename "$0"): $bin not built" >&2; exit 2; }
