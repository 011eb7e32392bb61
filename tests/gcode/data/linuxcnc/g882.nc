o<g882> sub
(debug, in g882 x=[#1] y=[#2] z=[#3] r=[#4], next is M75)
m75p1q47
o<g882> endsub [1]
m2

