#!/usr/bin/env bash
# Installs every Debian 12 package that cyclopt's build, tests and benchmarks need.
# Idempotent; run as root (or with sudo). Packages come only from Debian's archive.
#   --slurm  also Slurm and munge, for the Slurm executor's integration test (CI passes it; without
#            them that test is skipped)
#   --java   also a JDK and LCM's Java library, for the Java LCM types (lcm-spy, log decoding;
#            without them the types and their test are not built)
#   --browser also chromium and Node.js, and puppeteer-core (npm, pinned) in $BROWSER_TEST_PREFIX,
#            for the dashboard's browser test (CI passes it; without them that test is skipped)
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libeigen3-dev                 # linear algebra, fixed-size types
  coinor-libipopt-dev           # Ipopt 3.11.9 with MUMPS (pkg-config: ipopt)
  liblcm-dev liblcm-bin         # LCM 1.3.1: library, lcm-gen, lcm-logger
  libglib2.0-dev                # needed by lcm.pc
  libsqlite3-dev sqlite3        # results database and the sqlite3 shell for queries
  libssl-dev                    # OpenSSL libcrypto: HMAC-SHA256 message authentication
  nlohmann-json3-dev            # JSON specs
  libcpp-httplib-dev            # HTTP server of cyclopt-web (the dashboard)
  libcairo2-dev fonts-dejavu-core  # plots (PNG, SVG, PDF) and their font
  libgtest-dev libgmock-dev     # unit tests
  libbenchmark-dev              # benchmarks
  iproute2 util-linux           # ip / unshare for network-namespace integration tests
  pybind11-dev python3-dev      # the Python package (python/, docs/python.md)
  python3-numpy python3-pandas python3-matplotlib python3-pytest  # ... its arrays, tables, figures and tests
)
# Where --browser installs puppeteer-core; tests/web/dashboard_browser.sh looks there.
BROWSER_TEST_PREFIX=/opt/cyclopt-browser-test
PUPPETEER_CORE_VERSION=24.10.0  # drives Debian's chromium over the DevTools protocol; needs Node >= 18
browser=0
for option in "$@"; do
  case "$option" in
    --browser) browser=1; packages+=(chromium nodejs) ;;
    --slurm) packages+=(slurmctld slurmd slurm-client munge) ;;  # single-node test cluster: deploy/slurm/local-cluster.sh
    --java) packages+=(default-jdk-headless liblcm-java) ;;      # javac, /usr/share/java/lcm.jar, lcm-spy
    *) echo "install-deps: unknown option '$option' (--slurm, --java, --browser)" >&2; exit 2 ;;
  esac
done

# npm: Debian's package, unless a Node.js that brings its own npm is installed already.
if [ $browser = 1 ] && ! command -v npm > /dev/null; then packages+=(npm); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
  echo "install-deps: installed ${missing[*]}"
fi
if [ $browser = 1 ]; then
  installed=$(node -p "require('$BROWSER_TEST_PREFIX/node_modules/puppeteer-core/package.json').version" 2>/dev/null || true)
  if [ "$installed" = "$PUPPETEER_CORE_VERSION" ]; then
    echo "install-deps: puppeteer-core $installed present in $BROWSER_TEST_PREFIX"
  else
    $SUDO npm install --prefix "$BROWSER_TEST_PREFIX" --no-audit --no-fund --omit=dev "puppeteer-core@$PUPPETEER_CORE_VERSION"
    echo "install-deps: installed puppeteer-core $PUPPETEER_CORE_VERSION in $BROWSER_TEST_PREFIX"
  fi
fi
