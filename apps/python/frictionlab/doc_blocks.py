"""Generated blocks of Markdown documents: the text between <!-- NAME --> and <!-- /NAME --> is
what a script measured, and the script replaces it (frictionlab.li2020_claims,
frictionlab.lattice_convergence)."""
import re


def replace_block(path: str, name: str, text: str) -> None:
    """Replaces what stands between the `name` markers of the file at `path` with `text`; raises
    ValueError, leaving the file as it was, unless it has exactly one such block."""
    with open(path) as f:
        old = f.read()
    new, n = re.subn(rf"(<!-- {re.escape(name)} -->\n).*?(<!-- /{re.escape(name)} -->)",
                     lambda m: m[1] + text + m[2], old, flags=re.S)
    if n != 1:
        raise ValueError(f"{path}: {n} <!-- {name} --> blocks, not one")
    with open(path, "w") as f:
        f.write(new)
