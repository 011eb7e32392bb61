(Parameter number out of range)
#2=99999
G0 X EXISTS[###2]
M2
