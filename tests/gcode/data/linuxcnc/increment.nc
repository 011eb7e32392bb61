O<increment> sub
g91 g0 x#1 y#2
g90
O<increment> endsub
