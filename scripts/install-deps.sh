#!/usr/bin/env bash
# Installs the Debian packages hstmon's host build needs. Idempotent: does nothing when
# every package is already installed; otherwise runs `apt-get update` once, then
# `apt-get install -y`. Needs root (or sudo).
set -euo pipefail

packages=(
  cmake g++ make              # toolchain
  pkg-config                  # the C-API consumer test (tests/consumers/pkg_config.sh)
  dpkg-dev                    # dpkg-shlibdeps: the .deb's dependencies (scripts/release.sh)
  libeigen3-dev               # fixed-size linear algebra in lib/; fitting on the host
  libboost-dev                # Boost.Odeint: stiff reference solver (rosenbrock4), RK4 benchmark
  libcli11-dev                # command-line parsing of hstmon / hstmon-sim
  nlohmann-json3-dev          # parameter files and --json output
  libfmt-dev                  # formatting of reports and CSV output
  zlib1g-dev                  # gzip-compressed logs (.csv.gz) read by both log readers
  gnuplot-nox                 # residual plots (--plot)
  chromium                    # headless render of the HTML reports in tests/cli/test_report_html
  libpng-dev                  # that test reads chromium's screenshot to check it is not blank
  libgtest-dev                # unit tests
  libbenchmark-dev            # benchmarks
  valgrind                    # instruction counts (callgrind)
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib  # Cortex-M4F firmware
  qemu-system-arm             # runs the firmware (mps2-an386) in tests/firmware and footprint.sh
  g++-aarch64-linux-gnu qemu-user googletest  # aarch64 cross build; lib tests under qemu-aarch64
  clang libclang-rt-14-dev    # libFuzzer + ASan/UBSan runtimes for scripts/fuzz.sh
  clang-format clang-tidy     # the style check (scripts/style.sh)
  parallel                    # GNU parallel: the fleet recipe of docs/fleet.md and its test (tests/fleet)
  python3-dev pybind11-dev python3-pybind11  # the Python module (ports/python, docs/python.md)
  python3-numpy python3-pandas python3-matplotlib  # its arrays, DataFrames and plots
  python3-pytest python3-dask python3-distributed  # its tests (tests/python) and the Dask fleet recipe
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
