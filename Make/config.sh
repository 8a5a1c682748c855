# vheFoam: shared settings for every script (sourced, never run).
# Sets VHE_ROOT, the OpenFOAM run-time environment of Debian's package and
# this project's own bin/lib directories.  Build-only settings live in
# Make/buildEnv.sh so that users running cases never need the headers.

VHE_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd -P)"
export VHE_ROOT

# Debian bookworm's OpenFOAM: v1912, double precision, 32-bit labels.
export WM_PROJECT=OpenFOAM
export WM_PROJECT_VERSION=v1912
export WM_ARCH=linux64
export WM_COMPILER=Gcc
export WM_COMPILER_TYPE=system
export WM_COMPILER_LIB_ARCH=64
export WM_PRECISION_OPTION=DP
export WM_LABEL_SIZE=32
export WM_LABEL_OPTION=Int32
export WM_COMPILE_OPTION=Opt
export WM_MPLIB=SYSTEMOPENMPI
export WM_OPTIONS=linux64GccDPInt32Opt
export FOAM_MPI=openmpi-system
export MPI_ARCH_PATH=/usr/lib/x86_64-linux-gnu/openmpi

# Run time: Debian installs etc/ here and the libraries in /usr/lib.
export WM_PROJECT_DIR=/usr/share/openfoam
export FOAM_ETC=$WM_PROJECT_DIR/etc
export FOAM_LIBBIN=/usr/lib
export FOAM_APPBIN=/usr/bin

# This project's build output (ignored by git, never under /usr).
export FOAM_USER_APPBIN="$VHE_ROOT/platforms/$WM_OPTIONS/bin"
export FOAM_USER_LIBBIN="$VHE_ROOT/platforms/$WM_OPTIONS/lib"
export FOAM_SITE_APPBIN="$FOAM_USER_APPBIN"
export FOAM_SITE_LIBBIN="$FOAM_USER_LIBBIN"
# The user's own directory and run directory, where OpenFOAM puts them
# (cases are copied there from $VHE_ROOT/tutorials; nothing creates it)
export WM_PROJECT_USER_DIR="$HOME/OpenFOAM/${USER:-$(id -un)}-$WM_PROJECT_VERSION"
export FOAM_RUN="$WM_PROJECT_USER_DIR/run"
export FOAM_SIGFPE=true

case ":$PATH:" in
    *":$FOAM_USER_APPBIN:"*) ;;
    *) export PATH="$VHE_ROOT/bin:$FOAM_USER_APPBIN:$PATH" ;;
esac
case ":${LD_LIBRARY_PATH:-}:" in
    *":$FOAM_USER_LIBBIN:"*) ;;
    *) export LD_LIBRARY_PATH="$FOAM_USER_LIBBIN${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ;;
esac

# mpirun as root (CI and containers run as root) needs these two.
if [ "$(id -u)" = 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1
    export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
