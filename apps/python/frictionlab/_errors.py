"""The exception a scene with errors raises."""
from typing import List, NamedTuple


class Diagnostic(NamedTuple):
    """One error of a scene: where it is (file, 1-based line and column; 0 if unknown), the key path
    (e.g. "friction.mu_s", empty for whole-file errors) and the message."""

    file: str
    line: int
    column: int
    key_path: str
    message: str

    def __str__(self) -> str:
        where = f"{self.file}:{self.line}:{self.column}" if self.line else self.file
        key = f"{self.key_path}: " if self.key_path else ""
        return f"{where}: error: {key}{self.message}"


class SceneError(ValueError):
    """A scene that does not validate. `diagnostics` lists every error, as `frictionlab check`
    prints them; str(error) is that printout."""

    def __init__(self, message: str, diagnostics: list):
        super().__init__(message)
        self.diagnostics: List[Diagnostic] = [Diagnostic(*d) for d in diagnostics]
