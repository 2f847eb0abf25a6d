#!/bin/sh
# Installs the Debian packages libgeneric needs; does nothing when they are all present.
set -e
PKGS="build-essential pkg-config libpng-dev libopenimageio-dev openimageio-tools libcmocka-dev libembree-dev libassimp-dev colord-data gnuplot-nox povray clang libclang-rt-14-dev valgrind help2man libopenmpi-dev openmpi-bin libopencolorio-dev opencolorio-tools libopenexr-dev hyperfine python3 python3-cffi python3-numpy python3-pytest python3-matplotlib libopenvdb-dev python3-openvdb"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "deps: installing$missing" >&2
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
