(Named parameter not terminated)
G0 X EXISTS[#<foo]
M2
