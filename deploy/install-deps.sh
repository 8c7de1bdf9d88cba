#!/usr/bin/env bash
# Installs every Debian 12 package that cyclopt's build, tests and benchmarks need.
# Idempotent; run as root (or with sudo). Packages come only from Debian's archive.
#   --slurm  also Slurm and munge, for the Slurm executor's integration test (CI passes it; without
#            them that test is skipped)
#   --java   also a JDK and LCM's Java library, for the Java LCM types (lcm-spy, log decoding;
#            without them the types and their test are not built)
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
  libcairo2-dev fonts-dejavu-core  # plots (PNG, SVG, PDF) and their font
  libgtest-dev libgmock-dev     # unit tests
  libbenchmark-dev              # benchmarks
  iproute2 util-linux           # ip / unshare for network-namespace integration tests
  pybind11-dev python3-dev      # the Python package (python/, docs/python.md)
  python3-numpy python3-pandas python3-matplotlib python3-pytest  # ... its arrays, tables, figures and tests
)
for option in "$@"; do
  case "$option" in
    --slurm) packages+=(slurmctld slurmd slurm-client munge) ;;  # single-node test cluster: deploy/slurm/local-cluster.sh
    --java) packages+=(default-jdk-headless liblcm-java) ;;      # javac, /usr/share/java/lcm.jar, lcm-spy
    *) echo "install-deps: unknown option '$option' (--slurm, --java)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: installed ${missing[*]}"
