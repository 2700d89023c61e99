#!/usr/bin/env python3
"""The repository stands alone: no file of the product cites the working material outside it
(../shared/docs, ../shared/paper) or a notes file by a bare name, and every `docs/NAME.md` it
cites exists. The shared capture (../shared/data) may be named as the place of data the
repository cannot carry (its licence), never as documentation. Exits 1 listing every fault."""
import pathlib
import re
import sys

ROOTS = ["README.md", "Cargo.toml", "src", "host-tests", "bounce-table", "contact-bounce-c",
         "examples", "docs", "scripts", "memory.x", "build.rs", ".ci"]
SUFFIXES = {".rs", ".md", ".toml", ".sh", ".py", ".c", ".h", ".ld", ".x", ""}
OUTSIDE = re.compile(r"\.\./shared/(?!data\b)[\w./-]*")
BARE = re.compile(r"(?<![\w/.-])(physics|embedded|style)\.md")
CITED = re.compile(r"(?<![\w/.-])docs/([\w./-]+\.md)")

faults = []
for root in ROOTS:
    path = pathlib.Path(root)
    files = [path] if path.is_file() else sorted(p for p in path.rglob("*") if p.is_file())
    for f in files:
        if f.suffix not in SUFFIXES or "target" in f.parts or f.name == "doc-links.py":
            continue
        try:
            text = f.read_text()
        except UnicodeDecodeError:
            continue
        for n, line in enumerate(text.splitlines(), 1):
            for m in OUTSIDE.finditer(line):
                faults.append(f"{f}:{n}: cites {m.group(0)}, outside the repository")
            for m in BARE.finditer(line):
                faults.append(f"{f}:{n}: cites {m.group(0)} by a bare name (docs/{m.group(0)}?)")
            for m in CITED.finditer(line):
                if not pathlib.Path("docs", m.group(1)).exists():
                    faults.append(f"{f}:{n}: cites docs/{m.group(1)}, which does not exist")
if faults:
    sys.exit("\n".join(faults))
print("every citation points inside the repository")
