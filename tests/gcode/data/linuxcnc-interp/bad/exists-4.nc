(Unknown word starting with f)
G0 X EXISTS[#foo]
M2
