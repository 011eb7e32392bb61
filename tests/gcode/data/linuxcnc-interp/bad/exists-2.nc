(Expected ] reading bracketed parameter)
G0 X EXISTS[#1+#2]
M2
