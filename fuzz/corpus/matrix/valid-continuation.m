map_1 = [ 0, 0, 1 ; ... cont
 1 0 0 ; ] ; % end
