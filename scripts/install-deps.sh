#!/usr/bin/env bash
# Installs rayvec's build and test dependencies from Debian 12 packages (apt-get; sudo when not root).
# Skips apt entirely when everything is already installed. Embree is optional (benchmark rival only):
# pass --with-embree to install it too. --with-fuzz adds clang-14 and its libFuzzer runtime
# (scripts/fuzz.sh, tests/fuzz/); the normal build and test path does not need them. --with-mpi adds
# OpenMPI (scripts/test_mpi.sh, docs/distributed.md). --with-ccache adds ccache (CI shares compiled objects
# between its configurations).
set -euo pipefail
packages=(build-essential cmake pkg-config
          libtinyobjloader-dev libfast-float-dev libopenimageio-dev openimageio-tools libopenexr-dev libpng-dev zlib1g-dev libjpeg-dev
          libglm-dev nlohmann-json3-dev libcli11-dev
          libgtest-dev libgmock-dev libbenchmark-dev libgmp-dev clang-format
          python3             # scripts/*.py, and the test that runs the benchmark scene's script
          llvm                # llvm-mca: scripts/port_model.py and the test of the kernel loop's length
          assimp-testmodels)  # real-world OBJ/MTL files for tests/scene and tests/render (skipped without)
for flag in "$@"; do
  case "$flag" in
    --with-embree) packages+=(libembree-dev) ;;
    --with-fuzz) packages+=(clang-14 libclang-rt-14-dev) ;;
    --with-mpi) packages+=(openmpi-bin libopenmpi-dev) ;;
    --with-ccache) packages+=(ccache) ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
