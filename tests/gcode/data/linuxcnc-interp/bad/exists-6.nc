;bad number format (conversion failed) parsing ''
G0 X EXISTS[#]
M2
