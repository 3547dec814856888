#!/usr/bin/python3
"""The core's folders are layers: a file may include only from its own folder and the folders
listed before it (share/docs/architecture.md). Prints every include that points upward."""
import pathlib, re, sys

LAYERS = ['base', 'model', 'plugins', 'scene', 'output', 'simulation']
core = pathlib.Path(sys.argv[1])
include = re.compile(r'#include\s+"(?:frictionlab/)?([a-z_]+)/[a-z_0-9]+\.hpp"')
upward = []
files = [f for d in (core / 'include' / 'frictionlab', core / 'src') for f in d.rglob('*')
         if f.suffix in ('.hpp', '.cpp', '.in')]
for f in files:
    room = f.relative_to(core).parts[-2]
    if room not in LAYERS:
        upward.append(f'{f}: not in a layer folder ({", ".join(LAYERS)})')
        continue
    for n, line in enumerate(f.read_text().splitlines(), 1):
        m = include.search(line)
        if m and m.group(1) in LAYERS and LAYERS.index(m.group(1)) > LAYERS.index(room):
            upward.append(f'{f}:{n}: {room} includes {m.group(1)}: {line.strip()}')
print('\n'.join(upward) or f'{len(files)} files, every include points to its own layer or one below')
sys.exit(1 if upward else 0)
