#!/usr/bin/env bash
# Installs the Debian 12 packages gearcoupling builds and runs with. Idempotent; needs root
# (or sudo). Both README commands call it first.
set -euo pipefail
packages=(
  cmake g++ make
  ninja-build     # the build trees of tests/run_all.sh and tests/run_fuzz.sh
  libeigen3-dev
  libprotobuf-dev protobuf-compiler
  libspdlog-dev libfmt-dev libcli11-dev
  cyclonedds-dev cyclonedds-tools
  googletest libgtest-dev libgmock-dev libbenchmark-dev
  libjs-chart.js  # Chart.js, inlined into validate's HTML report
  chromium        # headless, checks the HTML report in the suite (tests/validation/report_browser_test.cc)
  chromium-driver python3-selenium python3-pytest  # the dashboard's browser test (tests/dashboard/)
  libcpp-httplib-dev  # gearcoupling-dashboard's HTTP server (pkg-config cpp-httplib)
  prometheus      # promtool checks /metrics in the suite (tests/dashboard/)
  python3-prometheus-client  # its text parser reads /metrics in the suite (tests/dashboard/)
  clang libclang-rt-14-dev  # the libFuzzer targets of fuzz/ (tests/run_fuzz.sh)
  dpkg-dev file pkg-config  # tests/packaging
  debhelper dh-python help2man lintian iproute2  # the .debs (debian/: dpkg-buildpackage) and their test
  python3-dev pybind11-dev python3-numpy  # the Python module (clients/python, docs/python.md)
  python3-pytest python3-pandas python3-matplotlib  # its tests and examples
  openssl         # deploy/security/make-security.sh (CA, certificates, signed documents, CRL)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
