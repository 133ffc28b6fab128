#!/usr/bin/env bash
# Installs what TimeCritical needs from Debian 12 (idempotent: skips when all
# packages are present). Never installs libvtk9-dev or python3-vtk9, which
# conflict with ParaView's bundled VTK.
#
#   install-deps.sh            install what is missing
#   install-deps.sh --list     print the package list
#   install-deps.sh --check    install nothing; verify that every package is
#                              installed, that the programs and Python modules
#                              the tests and the demo run are there, that the
#                              sanitizer and libFuzzer toolchains link, that a
#                              configure of the project finds every dependency,
#                              and that each file it finds belongs to a listed
#                              package or to one they depend on (so nothing
#                              works only because a developer machine happens
#                              to have an unlisted package). Exit status 1 on
#                              any problem.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

packages=(
  # toolchain and test tools
  cmake g++ make googletest libgtest-dev xvfb xauth
  # Clang and its runtime libraries (libFuzzer, sanitizers) for the fuzz
  # targets (scripts/run-fuzzers.sh); g++ brings GCC's sanitizer runtimes
  # for scripts/run-sanitizers.sh; llvm brings llvm-symbolizer, which turns
  # the addresses of sanitizer and fuzzer reports into file:line
  clang libclang-rt-14-dev llvm
  # ParaView 5.11 with its bundled VTK 9.2, and its Python modules
  paraview paraview-dev python3-paraview python3-numpy python3-matplotlib
  # libraries of the project (OpenImageIO: the library only, found without its
  # CMake package, which would also need openimageio-tools)
  libopenmesh-dev libopenimageio-dev libmeshoptimizer-dev
  # development files ParaView's CMake package looks for but does not depend on
  libopenmpi-dev libdouble-conversion-dev liblz4-dev liblzma-dev zlib1g-dev libexpat1-dev
  libpng-dev libjpeg-dev libtiff-dev libfreetype-dev libglew-dev libgl-dev libx11-dev
  libxt-dev libpugixml-dev libjsoncpp-dev libeigen3-dev libfmt-dev libutfcpp-dev libgl2ps-dev
  # Mesa's software OpenGL (llvmpipe) for headless rendering under Xvfb
  libgl1-mesa-dri
)
# Programs the tests, the demo and this script run.
programs=(cmake c++ clang++ make xvfb-run xauth Xvfb pvbatch dpkg-query apt-cache)
# Modules of /usr/bin/python3 (the interpreter that imports ParaView's VTK).
python_modules=(numpy matplotlib vtkmodules.vtkCommonCore paraview.simple)
# Cache entries of CMake's own optional probes, which the build uses when
# present and does without otherwise (checked in a fresh chroot): CTest's git
# and valgrind, FindX11's extension libraries, Fontconfig.
optional_probes='GITCOMMAND|MEMORYCHECK_COMMAND|COVERAGE_COMMAND|X11_X(au|composite|dmcp|ext|fixes|ft|render|ss)_LIB|Fontconfig_LIBRARY|pkgcfg_lib_PKG_FONTCONFIG_fontconfig'

missing_packages() {
  local p
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

# Installed packages that the listed ones pull in (Depends and Pre-Depends only,
# as apt-get --no-install-recommends installs them), the listed ones included.
dependency_closure() {
  apt-cache depends --recurse --installed --no-recommends --no-suggests --no-conflicts \
    --no-breaks --no-replaces --no-enhances "${packages[@]}" 2>/dev/null |
    sed -n -e 's/^\([a-z0-9][^ :<>]*\)\(:[a-z0-9]*\)\?$/\1/p' \
           -e 's/^ *\(Pre\)\?Depends: \([a-z0-9][^ :<>]*\)\(:[a-z0-9]*\)\?$/\2/p' |
    sort -u
}

check() {
  local problems=0 p
  mapfile -t missing < <(missing_packages)
  if [ ${#missing[@]} -gt 0 ]; then
    echo "check: packages not installed: ${missing[*]}"
    problems=1
  else
    echo "check: all ${#packages[@]} packages installed"
  fi
  for p in "${programs[@]}"; do
    command -v "$p" >/dev/null 2>&1 || { echo "check: program not found: $p"; problems=1; }
  done
  for p in "${python_modules[@]}"; do
    /usr/bin/python3 -c "import $p" >/dev/null 2>&1 ||
      { echo "check: /usr/bin/python3 cannot import $p"; problems=1; }
  done
  [ $problems -eq 0 ] && echo "check: programs (${programs[*]}) and Python modules (${python_modules[*]}) found"

  # The sanitizer and fuzzing toolchains link (scripts/run-sanitizers.sh with
  # c++, scripts/run-fuzzers.sh with clang++ and libFuzzer).
  local toolchain
  toolchain="$(mktemp -d "${TMPDIR:-/tmp}/timecritical-toolchain.XXXXXX")"
  echo 'int main() { return 0; }' >"$toolchain/main.cxx"
  echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' >"$toolchain/fuzz.cxx"
  if ! c++ -fsanitize=address,undefined "$toolchain/main.cxx" -o "$toolchain/main" >"$toolchain/log" 2>&1; then
    echo "check: c++ cannot link with -fsanitize=address,undefined:"; head -5 "$toolchain/log"; problems=1
  elif ! clang++ -fsanitize=fuzzer,address,undefined "$toolchain/fuzz.cxx" -o "$toolchain/fuzz" >"$toolchain/log" 2>&1; then
    echo "check: clang++ cannot link a libFuzzer target (libclang-rt-14-dev):"; head -5 "$toolchain/log"; problems=1
  else
    echo "check: c++ links with AddressSanitizer + UBSan, clang++ links libFuzzer targets"
  fi
  rm -rf "$toolchain"

  # A configure of the project in a scratch folder: every find_package and
  # find_program the build runs, with optional dependencies made mandatory.
  local scratch
  scratch="$(mktemp -d "${TMPDIR:-/tmp}/timecritical-check.XXXXXX")"
  trap 'rm -rf "$scratch"' RETURN
  if ! cmake -S "$root" -B "$scratch" -DCMAKE_BUILD_TYPE=Release \
      -DTIMECRITICAL_REQUIRE_ALL_DEPENDENCIES=ON >"$scratch/configure.log" 2>&1; then
    echo "check: configure failed:"
    grep -A12 -E "CMake Error" "$scratch/configure.log" | head -40
    return 1
  fi
  echo "check: configure found every dependency"

  # Every file or folder under /usr that the configure found must come from a
  # listed package or a dependency of one.
  mapfile -t closure < <(dependency_closure)
  declare -A allowed=()
  for p in "${closure[@]}"; do allowed[$p]=1; done
  local path owners owner ok checked=0
  while IFS= read -r path; do
    [ -e "$path" ] || continue
    owners="$(dpkg-query -S "$path" 2>/dev/null | sed -n 's/^\([^:]*\)\(:[a-z0-9]*\)\?: .*/\1/p' | tr ',' '\n' | tr -d ' ' | sort -u)"
    [ -n "$owners" ] || continue
    checked=$((checked + 1))
    ok=0
    for owner in $owners; do
      [ -n "${allowed[$owner]:-}" ] && ok=1
    done
    if [ $ok -eq 0 ]; then
      echo "check: $path comes from $(echo $owners | tr ' ' ','), which no listed package depends on: add it to scripts/install-deps.sh"
      problems=1
    fi
  done < <(grep -v -E "^($optional_probes):" "$scratch/CMakeCache.txt" |
           sed -n -e 's/^[A-Za-z0-9_.+-]*:\(FILEPATH\|PATH\|STRING\|INTERNAL\)=\(\/usr\/[^;]*\)$/\2/p' |
           grep -v -e '/usr/local/' -e 'NOTFOUND' | sort -u)
  echo "check: $checked paths found by the configure belong to packages; ${#closure[@]} packages in the dependency closure"
  return $problems
}

case "${1:-}" in
  --list)
    printf '%s\n' "${packages[@]}"
    exit 0
    ;;
  --check)
    if check; then
      echo "check: OK"
      exit 0
    fi
    echo "check: FAILED (run scripts/install-deps.sh, or fix its package list)"
    exit 1
    ;;
  "") ;;
  *)
    echo "usage: $0 [--check | --list]" >&2
    exit 2
    ;;
esac

mapfile -t missing < <(missing_packages)
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
