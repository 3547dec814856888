#!/usr/bin/python3
"""The apps' folders are rooms with a direction (share/docs/architecture.md): the campaign engine
stands on the core alone, the command on the engine and the core, and the command's commands/ are
its own, included from nowhere else. Prints every include that breaks this.
Usage: check_app_layers.py SOURCE_DIR (its apps/ is checked)."""
import pathlib
import re
import sys

CORE_ROOMS = ('base', 'model', 'plugins', 'scene', 'output', 'simulation')
# The rooms each room may include from, besides its own.
MAY_INCLUDE = {
    'campaign': {'core'},
    'frictionlab': {'core', 'campaign', 'commands'},
    'commands': {'core', 'campaign', 'frictionlab'},
    'python': {'core', 'campaign', 'frictionlab'},
    'benchmarks': {'core', 'campaign', 'plugins'},
}
include = re.compile(r'#include\s+"([^"]+)"')


def room_of(path, apps):
    """The room of a file below apps/: its top folder, or commands for apps/frictionlab/commands."""
    parts = path.relative_to(apps).parts
    return 'commands' if parts[:2] == ('frictionlab', 'commands') else parts[0]


def room_included(target, source, root, apps):
    """The room an include names: a core or campaign header by its frictionlab/<room>/ prefix, a
    file beside the includer by its place, else a plugin's header found through the include path."""
    parts = pathlib.PurePosixPath(target).parts
    if len(parts) == 3 and parts[0] == 'frictionlab':
        return 'core' if parts[1] in CORE_ROOMS else parts[1]
    beside = (source.parent / target).resolve()
    if beside.exists() and apps.resolve() in beside.parents:
        return room_of(apps / beside.relative_to(apps.resolve()), apps)
    if any((root / 'plugins').glob(f'*/{target}')):
        return 'plugins'
    return None


def main():
    root = pathlib.Path(sys.argv[1])
    apps = root / 'apps'
    files = sorted(f for f in apps.rglob('*') if f.suffix in ('.hpp', '.cpp'))
    problems = []
    for f in files:
        room = room_of(f, apps)
        allowed = MAY_INCLUDE.get(room)
        if allowed is None:
            problems.append(f'{f}: not in a room of apps/ ({", ".join(MAY_INCLUDE)})')
            continue
        for n, line in enumerate(f.read_text().splitlines(), 1):
            m = include.search(line)
            if not m:
                continue
            target = room_included(m.group(1), f, root, apps)
            if target is None:
                problems.append(f'{f}:{n}: {room} includes a file outside every room: {line.strip()}')
            elif target != room and target not in allowed:
                problems.append(f'{f}:{n}: {room} includes {target}: {line.strip()}')
    print('\n'.join(problems) or f'{len(files)} files, every include points to its own room or one it stands on')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
