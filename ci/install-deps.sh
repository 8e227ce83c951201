#!/usr/bin/env bash
# Installs every Debian package GeoSPH needs. Idempotent: does nothing when all are present.
# Why each package:
#   cmake g++ make          build
#   libeigen3-dev           small dense tensors (stress, strain, Jacobians)
#   libgsl-dev              special functions, series and quadrature for analytical references
#   libhdf5-dev             particle output and restart (HDF5 + XDMF index)
#   nlohmann-json3-dev      scene files and result records (well-kept header-only JSON parser)
#   libcli11-dev            the `geosph` command line (subcommands, typed options, --help)
#   libgtest-dev            unit tests
#   libbenchmark-dev        throughput benchmarks (particle-steps per second)
#   python3-matplotlib python3-numpy python3-h5py   report generator and its figures
#   liggghts                DEM references for granular collapse (reference/dem)
#   libcgal-dev             closed triangulated surfaces (STL shapes): AABB-tree distances and the
#                           side-of-mesh inside test, robust where a hand-written ray cast is not
set -euo pipefail
PKGS=(cmake g++ make pkg-config libeigen3-dev libgsl-dev libhdf5-dev nlohmann-json3-dev libcli11-dev
      libgtest-dev libbenchmark-dev python3 python3-matplotlib python3-numpy python3-h5py liggghts
      libcgal-dev)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
