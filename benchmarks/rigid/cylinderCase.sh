# Sourced by cylinder.sh and galilean.sh: one rigid cylinder (D = 0.1 m,
# axis z) in one liquid of rho 1, no gravity.
# cylinderCase DIR X Y NU MOTION: its setBodiesDict (centre (X Y 0)),
# vheProperties (liquid and cylinder of viscosity NU; MOTION the rigid
# material's motion entries, e.g. "motion fixed;") and g
cylinderCase() {
    local d=$1 x=$2 y=$3 nu=$4 motion=$5
    cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { cylinder { material cylinder; shape cylinder; centre ($x $y 0); radius 0.05; axis (0 0 1); } }
DICT
    cat > "$d/constant/vheProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object vheProperties; }
fluids { liquid { rho [1 -3 0 0 0 0 0] 1; nu [0 2 -1 0 0 0 0] $nu; } }
solids { cylinder { rho [1 -3 0 0 0 0 0] 1; nu [0 2 -1 0 0 0 0] $nu;
                    rigid yes; $motion } }
DICT
    cat > "$d/constant/g" <<DICT
FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions [0 1 -2 0 0 0 0]; value (0 0 0);
DICT
}
