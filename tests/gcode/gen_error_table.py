#!/usr/bin/env python3
"""Prints the error-code table of docs/gcode.md from gcode/error.h and gcode/error.cpp.

usage (from the repository root): python3 tests/gcode/gen_error_table.py
"""
import re
import sys

h = open('gcode/error.h').read()
nums = dict(re.findall(r'\n\s+(\w+) = (\d+),', h))
c = open('gcode/error.cpp').read()
start = c.index('constexpr ErrorInfo kErrors[]')
body = c[start:c.index('\n};', start)]
tr = r'QT_TRANSLATE_NOOP\(\s*"frezka::gcode",\s*((?:"[^"]*"\s*)+)\)'
ents = re.findall(r'\{ErrorCode::(\w+),\s*"\w+",\s*' + tr + r',\s*' + tr + r'\}', body, re.S)


def text(literals):
    return ''.join(re.findall(r'"([^"]*)"', literals)).replace('|', '\\|')


print('| Code | Name | Message (English; %1 = the word or value) | What to do |')
print('|---:|---|---|---|')
for name, message, hint in ents:
    print('| %s | `%s` | %s | %s |' % (nums[name], name, text(message), text(hint)))
if len(ents) != len(nums):
    sys.exit('error.cpp has %d entries for %d codes' % (len(ents), len(nums)))
