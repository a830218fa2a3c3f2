#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The walk of one fit's data (tools/data-walk): from a trace of the main thread's function entries and exits,
the calls of generator functions that take the measured data (a parameter `Measurement const&`), from the first
such call to the end of the run. A repeated call path (the same chain of such functions, as in a loop over
orders) is walked once. A room is a source file. Prints the rooms, the entries into a room from another, the
returns to a higher room (from a callee in one file back to its caller in another) and the entries into a room
already left (one not on the current path), then the walk itself (^ marks a return).
  tools/data-walk.py ADMITGEN_BINARY TRACE"""
import subprocess
import sys

binary, trace = sys.argv[1], sys.argv[2]
addr2line = subprocess.Popen(['addr2line', '-f', '-C', '-e', binary], stdin=subprocess.PIPE,
                             stdout=subprocess.PIPE, text=True)
resolved = {}


def resolve(address):
    """(demangled function, its file under generator/ or None)"""
    if address not in resolved:
        addr2line.stdin.write(address + '\n')
        addr2line.stdin.flush()
        function = addr2line.stdout.readline().strip()
        path = addr2line.stdout.readline().strip().split(':')[0]
        at = path.find('/generator/')
        resolved[address] = (function, path[at + len('/generator/'):] if at >= 0 else None)
    return resolved[address]


def data_calls(lines):
    """The entries and exits ('E'/'X', file, function) of the data-carrying calls, each call path once."""
    events, stack, seen, skip_from, started = [], [], set(), None, False
    for line in lines:
        kind, address = line.split()
        function, path = resolve(address)
        if path is None:
            continue
        carries = 'Measurement const&' in function
        if not started:
            if kind != 'E' or not carries:
                continue
            started = True
        if kind == 'E':
            if not carries:
                stack.append(None)
                continue
            chain = tuple(s[0] for s in stack if s is not None) + (function,)
            stack.append((function, path))
            if skip_from is None:
                if chain in seen:
                    skip_from = len(stack)
                else:
                    seen.add(chain)
                    events.append(('E', path, function))
        elif stack:
            top = stack.pop()
            if top is None:
                continue
            if skip_from is not None:
                if len(stack) + 1 == skip_from:
                    skip_from = None
                continue
            events.append(('X', top[1], top[0]))
    return events


with open(trace) as f:
    events = data_calls(f)
path, visited, walk = [], set(), []
entries = higher = again = 0
last_top = None  # the room of the last call made from outside the data-carrying functions
for kind, room, _ in events:
    if kind == 'E':
        here = path[-1] if path else last_top
        if room != here:
            entries += 1
            if room in visited and room not in path:
                again += 1
            visited.add(room)
            walk.append(room)
        path.append(room)
    else:
        path.pop()
        if not path:
            last_top = room
        elif path[-1] != room:
            higher += 1
            walk.append('^' + path[-1])
calls = sum(1 for e in events if e[0] == 'E')
print(f"{calls} distinct call paths; rooms {len(visited)}; entries into a room from another {entries}; "
      f"returns to a higher room {higher}; entries into a room already left {again}")
for room in sorted(visited):
    print('   ', room)
print(' '.join(walk))
