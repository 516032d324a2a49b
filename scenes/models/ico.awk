# ico.awk: the icosahedron and its subdivision, for the generators
# scenes/models/mkmodels.sh and scenes/bench/mkscenes.sh (awk -f ico.awk
# -f PROGRAM). Vertices are unit vectors VX[i], VY[i], VZ[i], i < nv.

# A new vertex: (x, y, z) pushed out to the unit sphere; its index.
function vert(x, y, z,   l) { l = sqrt(x * x + y * y + z * z); VX[nv] = x / l; VY[nv] = y / l; VZ[nv] = z / l; return nv++ }
# The midpoint vertex of edge (a, b), made once per edge (M), so that the
# faces on both sides share it exactly.
function mid(a, b,   k) {
    k = a < b ? a "," b : b "," a
    if (!(k in M)) M[k] = vert((VX[a] + VX[b]) / 2, (VY[a] + VY[b]) / 2, (VZ[a] + VZ[b]) / 2)
    return M[k]
}
# The icosahedron: its 12 vertices, and its 20 faces as "a b c" in F[1..20]
# (counter-clockwise seen from outside); returns 20.
function ico_base(   g) {
    g = (1 + sqrt(5)) / 2; nv = 0
    vert(-1, g, 0); vert(1, g, 0); vert(-1, -g, 0); vert(1, -g, 0)
    vert(0, -1, g); vert(0, 1, g); vert(0, -1, -g); vert(0, 1, -g)
    vert(g, 0, -1); vert(g, 0, 1); vert(-g, 0, -1); vert(-g, 0, 1)
    return split("0 11 5|0 5 1|0 1 7|0 7 10|0 10 11|1 5 9|5 11 4|11 10 2|10 7 6|7 1 8|" \
                 "3 9 4|3 4 2|3 2 6|3 6 8|3 8 9|4 9 5|2 4 11|6 2 10|8 6 7|9 8 1", F, "|")
}
