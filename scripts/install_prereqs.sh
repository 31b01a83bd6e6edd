#!/usr/bin/env bash
# Installs what LANDYN needs on Debian 12: compilers and libraries from Debian's packages, and the
# Python post-processing packages (pinned in post/requirements.txt), FORD (docs/api/requirements.txt)
# and the packages landyn_post (post/) and landyn (python/, the Python API) into a virtual environment
# .venv in the source tree. Run as root or with sudo available.
set -euo pipefail
cd "$(dirname "$0")/.."

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# fypp: the Fortran preprocessor that generates the HDF5 wrappers from src/output/*.fypp
PKGS="gfortran gcc g++ make cmake liblapack-dev libblas-dev libhdf5-dev hdf5-tools \
      libopenmpi-dev openmpi-bin python3 python3-venv python3-pip fypp"
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "install_prereqs: installing Debian packages:$missing"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends $missing
fi

if [ ! -x .venv/bin/python ]; then
  echo "install_prereqs: creating the Python environment .venv"
  python3 -m venv .venv
fi
.venv/bin/python -m pip install -q --upgrade pip
.venv/bin/python -m pip install -q -r post/requirements.txt
.venv/bin/python -m pip install -q -r docs/api/requirements.txt   # FORD, for the api_docs target
.venv/bin/python -m pip install -q -e post/
.venv/bin/python -m pip install -q -e python/      # the landyn package (Python API over build/release/liblandyn.so)
echo "install_prereqs: done"
