"""Reproductions of published papers by one command: `frictionlab reproduce PAPER -o DIR` (or
`python3 -m frictionlab.reproduce PAPER -o DIR`) runs what the paper shows and writes a report with
a verdict per statement (report.md in DIR)."""
