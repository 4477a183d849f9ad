*pattern # px py radius num_vertedges
0.001 0.0005 0.0001 2

*Q # dofs: x y z t
0 0 0 0
0.0005 0 0 0

*E # edges: v0 v1 dx dy
0 1 0 0
1 0 1 0
