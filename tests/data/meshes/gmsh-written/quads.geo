lc = 0.6;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {0, 1, 0, lc};
Circle(1) = {2, 1, 3};
out[] = Extrude {0, 0, 3} { Curve{1}; Layers{4}; Recombine; };
Physical Surface("wall") = {out[1]};
Physical Curve("bottom") = {1};
Physical Curve("top") = {out[0]};
Physical Point("corner") = {2};
