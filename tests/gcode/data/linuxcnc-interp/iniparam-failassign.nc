#<_ini[vars]toolchange_x> = 3.1415
(debug, notreached: #<_ini[vars]toolchange_x>)
M2
