%{
block
%}
0
