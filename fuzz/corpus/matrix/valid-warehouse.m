% warehouse.m - a 12x9 occupancy matrix for the path-planning demo (pathref sample)
% 0 = free, 1 = obstacle; first row of G is the top row of the map
% 障碍物栅格地图 (comments may hold any UTF-8)
G=[0 0 0 0 0 0 0 0 0 0 0 0;
   0 1 1 1 0 0 0 1 1 1 1 0;
   0 0 0 1 0 0 0 0 0 0 1 0;
   0,0,0,1,0,1,1,1,1,0,1,0; % a row written with commas
   1 1 0 1 0 0 ...
     0 0 1 0 0 0;
   0 0 0 0 0 0 1 0 1 1 1 0
   0 1 1 1 1 0 1 0 0 0 0 0
   0 0 0 0 1 0 0 0 1 1 0 1
   0 0 0 0 0 0 0 0 0 0 0 0];

% MM = size(G,1);  (the script's code is not part of the sample)
