# vheFoam: helper functions for Allwmake, Allrun, Alltest (sourced).

# Debian packages each stage needs.
# (libopenblas0-serial: the BLAS of the coupled step's LU, MUMPS; with
# Debian's reference BLAS test_stiff's stiff channel took 7.5 s, not 6.0)
VHE_BUILD_PACKAGES="openfoam libopenfoam openmpi-bin libopenmpi-dev gcc g++ make
 pkg-config check dpkg-dev xz-utils bzip2 gmsh gnuplot-nox libpetsc-real-dev
 libopenblas0-serial"
VHE_TEST_PACKAGES="python3"
VHE_RUN_PACKAGES="gmsh gnuplot-nox python3 bsdextrautils bc"
VHE_IMAGE_PACKAGES="paraview python3-paraview xvfb xauth"

# vhe_need_packages PKG...: install the missing ones (as root) or print the
# exact apt-get line and fail.
vhe_need_packages()
{
    local missing="" p
    for p in "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" \
            || missing="$missing $p"
    done
    [ -z "$missing" ] && return 0
    if [ "$(id -u)" = 0 ]; then
        echo "Installing Debian packages:$missing"
        export DEBIAN_FRONTEND=noninteractive
        apt-get update -qq >/dev/null || return 1
        # shellcheck disable=SC2086
        apt-get install -y -qq --no-install-recommends $missing >/dev/null \
            || { echo "apt-get install failed for:$missing" >&2; return 1; }
    else
        echo "Missing Debian packages. Run:" >&2
        echo "  sudo apt-get install --no-install-recommends$missing" >&2
        return 1
    fi
}

# The OpenFOAM v1912 headers and wmake, from Debian's own source package of
# the installed openfoam version, unpacked once into an ignored cache.
VHE_FOAM_CACHE="$VHE_ROOT/.cache/openfoam-v1912"

vhe_foam_source()
{
    local stamp="$VHE_FOAM_CACHE/.vhe-ready"
    [ -f "$stamp" ] && return 0

    local ver dl
    ver=$(dpkg-query -W -f='${Version}' openfoam) || return 1
    ver=${ver%+b*}    # binNMU suffix: the source version has none
    echo "Fetching OpenFOAM source package openfoam=$ver (headers and wmake)"

    if ! apt-get source --print-uris "openfoam=$ver" 2>/dev/null | grep -q "orig.tar"; then
        if [ "$(id -u)" = 0 ]; then
            echo "Enabling deb-src for the installed Debian release"
            . /etc/os-release
            cat > /etc/apt/sources.list.d/vhefoam-deb-src.sources <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: $VERSION_CODENAME $VERSION_CODENAME-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
            apt-get update -qq >/dev/null || return 1
        else
            echo "Enable a deb-src entry for your Debian release (as root), e.g." >&2
            echo "  /etc/apt/sources.list.d/deb-src.sources with 'Types: deb-src'" >&2
            echo "and run ./Allwmake again." >&2
            return 1
        fi
    fi

    dl="$VHE_ROOT/.cache/download"
    rm -rf "$dl" "$VHE_FOAM_CACHE"
    mkdir -p "$dl"
    ( cd "$dl" && apt-get source --download-only -qq "openfoam=$ver" >/dev/null 2>&1 ) \
        || { echo "apt-get source openfoam=$ver failed" >&2; return 1; }
    ( cd "$dl" && dpkg-source -q -x ./*.dsc src >/dev/null 2>&1 ) \
        || { echo "dpkg-source failed" >&2; return 1; }

    # Keep what building against the library needs, plus the solver sources
    # we read (interFoam and friends); drop tutorials, docs, other apps.
    mkdir -p "$VHE_FOAM_CACHE/applications/solvers"
    mv "$dl/src/wmake" "$dl/src/src" "$dl/src/etc" "$dl/src/META-INFO" "$VHE_FOAM_CACHE"/
    mv "$dl/src/applications/solvers/multiphase" "$VHE_FOAM_CACHE/applications/solvers/"
    rm -rf "$dl"

    ( vhe_build_env && cd "$WM_DIR/src" && make -s >/dev/null ) \
        || { echo "building wmake tools failed" >&2; return 1; }
    ( vhe_build_env \
      && for lib in OpenFOAM OSspecific/POSIX finiteVolume meshTools fileFormats \
                    surfMesh dynamicMesh dynamicFvMesh functionObjects/field \
                    sampling transportModels/twoPhaseMixture \
                    transportModels/interfaceProperties transportModels/incompressible \
                    transportModels/twoPhaseProperties; do
             "$WM_DIR/wmakeLnInclude" -silent "$FOAM_SRC/$lib" >/dev/null 2>&1 || exit 1
         done ) || { echo "wmakeLnInclude failed" >&2; return 1; }
    touch "$stamp"
}

# Build-time environment: wmake and the headers from the cache, linking
# against Debian's libraries in /usr/lib.
vhe_build_env()
{
    export WM_PROJECT_DIR="$VHE_FOAM_CACHE"
    export WM_DIR="$WM_PROJECT_DIR/wmake"
    export FOAM_SRC="$WM_PROJECT_DIR/src"
    export LIB_SRC="$FOAM_SRC"
    export FOAM_APP="$WM_PROJECT_DIR/applications"
    export WM_NCOMPPROCS=${WM_NCOMPPROCS:-$(nproc)}
    export VHE_C_BUILD="$VHE_ROOT/build/vhe"
    case ":$PATH:" in *":$WM_DIR:"*) ;; *) export PATH="$WM_DIR:$PATH" ;; esac
}
