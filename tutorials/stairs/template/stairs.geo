// Water falling down stairs (seed 003): the 2D stairs profile as
// rectangles on a grid of x and y lines, meshed with quadrilaterals
// (transfinite, recombined) and extruded one cell in z to hexahedra.
//   gmsh -3 stairs.geo          (Allrun: -setnumber dx <cell size>)
// Patches: walls (floor, steps, sides), top (closed lid), frontAndBack.
Mesh.MshFileVersion = 2.2;      // the format v1912's gmshToFoam reads

DefineConstant[ dx = 0.025 ];   // cell size [m]
nSteps = 3;                     // steps down from the left
stepWidth = 0.5;                // [m]
stepHeight = 0.2;               // [m]
H = 1.2;                        // height of the box above the lowest floor [m]

// Grid lines: x = i stepWidth (i = 0..nSteps+1), y = j stepHeight
// (j = 0..nSteps) and the lid at y = H.  Column i has its floor at
// y = (nSteps - i) stepHeight, i.e. on grid line j = nSteps - i.
nx = nSteps + 1;
For i In {0:nx}
    xs[i] = i*stepWidth;
EndFor
For j In {0:nSteps}
    ys[j] = j*stepHeight;
EndFor
ys[nSteps + 1] = H;
ny = nSteps + 1;

For i In {0:nx}
    For j In {0:ny}
        p[i*(ny + 1) + j] = newp; Point(p[i*(ny + 1) + j]) = {xs[i], ys[j], 0};
    EndFor
EndFor
For i In {0:nx-1}          // horizontal lines
    For j In {0:ny}
        hl[i*(ny + 1) + j] = newl;
        Line(hl[i*(ny + 1) + j]) = {p[i*(ny + 1) + j], p[(i + 1)*(ny + 1) + j]};
        Transfinite Line{hl[i*(ny + 1) + j]} = Round(stepWidth/dx) + 1;
    EndFor
EndFor
For i In {0:nx}            // vertical lines
    For j In {0:ny-1}
        vl[i*ny + j] = newl;
        Line(vl[i*ny + j]) = {p[i*(ny + 1) + j], p[i*(ny + 1) + j + 1]};
        Transfinite Line{vl[i*ny + j]} = Round((ys[j + 1] - ys[j])/dx) + 1;
    EndFor
EndFor

// The fluid rectangles: column i, layers j >= its floor
k = 0;
For i In {0:nx-1}
    For j In {nSteps - i:ny-1}
        cl = newll;
        Curve Loop(cl) = {hl[i*(ny + 1) + j], vl[(i + 1)*ny + j],
                          -hl[i*(ny + 1) + j + 1], -vl[i*ny + j]};
        s[k] = news; Plane Surface(s[k]) = {cl};
        Transfinite Surface{s[k]}; Recombine Surface{s[k]};
        k = k + 1;
    EndFor
EndFor

ext[] = Extrude {0, 0, dx} { Surface{s[]}; Layers{1}; Recombine; };

Physical Volume("internal") = {Volume{:}};
eps = 1e-6;
front[] = Surface In BoundingBox{-eps, -eps, -eps, xs[nx] + eps, H + eps, eps};
back[] = Surface In BoundingBox{-eps, -eps, dx - eps, xs[nx] + eps, H + eps, dx + eps};
top[] = Surface In BoundingBox{-eps, H - eps, -eps, xs[nx] + eps, H + eps, dx + eps};
walls[] = CombinedBoundary{ Volume{:}; };
walls[] -= front[]; walls[] -= back[]; walls[] -= top[];
Physical Surface("frontAndBack") = {front[], back[]};
Physical Surface("top") = {top[]};
Physical Surface("walls") = {walls[]};
