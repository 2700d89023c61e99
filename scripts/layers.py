#!/usr/bin/env python3
"""Layers: every import runs down, and no files import each other in a loop.

The core (`src/`) is five layers, lowest first; a file may import from its own layer or a
lower one, never a higher one:

    numeric   src/numeric/   the arithmetic every tier uses: Float, tuning, quadrature, tables
    physics   src/physics/   what a contact does: errors, the orbit, the mechanisms, a flight
    scene     src/scene/     a switch, validated once
    tiers     src/tiers/     how to predict: closed, averaged, map, exact; method, prediction
    debounce  src/debounce/  from a prediction to a window, and the debouncers on it

The desk tool (`bounce-table/src/`) is the same with its own layers: `support` (strict input,
threads), `capture` (one reader per format), `scene` (scene files, the catalogue, priors, the
reference), `stats` (fits, windows from captures, the Monte Carlo), `render` (formats, plots),
`commands` (the table mode and each subcommand), `cli`; and one subcommand never imports
another (`commands/replay` may not use `commands/calibrate`: what both need lives below).

`lib.rs` and `main.rs` sit above them all. Beyond the layers, the files themselves must not
import each other in a loop: the graph of `use` (and of inline `crate::`/`super::` paths)
between files has no cycle. A parent's `mod child;` is not an import, and neither are
`#[cfg(test)]` modules.

    python3 scripts/layers.py            # check; exit 1 with each violation
    python3 scripts/layers.py --graph    # also print every file's imports
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# (source folder, layers lowest first, the layer whose children may not import each other)
CRATES = [
    ("src", ["numeric", "physics", "scene", "tiers", "debounce"], None),
    ("bounce-table/src", ["support", "capture", "scene", "stats", "render", "commands", "cli"], "commands"),
]
SRC = ROOT / "src"
LAYERS = CRATES[0][1]


def strip_comments_and_tests(text):
    """Drop comments, strings' contents and a trailing #[cfg(test)] module."""
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r'"(?:[^"\\]|\\.)*"', '""', text)
    while True:
        m = re.search(r"#\[cfg\(test\)\]\s*mod \w+\s*\{", text)
        if not m:
            return text
        depth, i = 1, m.end()
        while depth and i < len(text):
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        text = text[: m.start()] + text[i:]


def expand_use_tree(tree):
    """`a::{b, c::{d, e}}` -> [a::b, a::c::d, a::c::e]."""
    tree = re.sub(r"\s+as\s+\w+", "", tree)
    tree = re.sub(r"\s+", "", tree)
    depth, start, parts = 0, 0, []
    out = []
    brace = tree.find("{")
    if brace < 0:
        return [tree]
    prefix = tree[:brace]
    inner = tree[brace + 1 : tree.rfind("}")]
    for i, ch in enumerate(inner):
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(inner[start:i])
            start = i + 1
    parts.append(inner[start:])
    for part in parts:
        if part:
            out.extend(prefix + p for p in expand_use_tree(part))
    return out


def module_of(path):
    """src/a/b.rs -> ['a', 'b']; src/a/mod.rs -> ['a']; src/lib.rs -> []."""
    rel = path.relative_to(SRC).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] in ("mod", "lib"):
        parts.pop()
    return parts


def file_of(module, files):
    """The deepest file that defines a prefix of the module path."""
    for n in range(len(module), -1, -1):
        prefix = module[:n]
        if prefix in files:
            return files[prefix]
    return None


def imports(path, text, files):
    """The files this file's paths name (through use trees and inline paths)."""
    here = module_of(path)
    is_dir_module = path.name in ("mod.rs", "lib.rs")
    # Inline modules (`mod sealed { ... }`): a `super::` inside one first leaves it.
    spans = []
    for m in re.finditer(r"\bmod\s+\w+\s*\{", text):
        depth, i = 1, m.end()
        while depth and i < len(text):
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        spans.append((m.end(), i))
    paths = []
    for m in re.finditer(r"\buse\s+([^;]+);", text):
        paths.extend((p, m.start()) for p in expand_use_tree(m.group(1)))
    bare = re.sub(r"\buse\s+[^;]+;", lambda m: " " * len(m.group(0)), text)
    paths.extend((m.group(1), m.start()) for m in re.finditer(r"\b((?:crate|super)(?:::\w+)+)", bare))
    found = set()
    for p, at in paths:
        segs = [s for s in p.split("::") if s]
        inline = sum(1 for a, b in spans if a <= at < b)
        while inline and segs and segs[0] == "super":
            segs, inline = segs[1:], inline - 1
        if inline and segs and segs[0] not in ("crate",):
            continue  # a path inside an inline module, to its own items
        if not segs:
            continue
        if not segs:
            continue
        if segs[0] == "crate":
            target = segs[1:]
        elif segs[0] in ("super", "self"):
            base = here
            while segs and segs[0] in ("super", "self"):
                if segs[0] == "super":
                    base = base[:-1]
                segs = segs[1:]
            target = base + segs
        else:
            # A path through a child module declared here (`kernel::Kernel` in exact/mod.rs).
            if not is_dir_module or tuple(here + segs[:1]) not in files:
                continue
            target = here + segs
        f = resolve(tuple(target), files)
        if f is not None and f != path:
            found.add(f)
    return found


REEXPORTS = {}


def reexports(path, files):
    """What a file re-exports: name -> the absolute path it names (`pub use a::B` -> B: a::B)."""
    if path not in REEXPORTS:
        here = module_of(path)
        base = here
        text = strip_comments_and_tests(path.read_text())
        table = {}
        for m in re.finditer(r"\bpub(?:\([^)]*\))?\s+use\s+([^;]+);", text):
            for p in expand_use_tree(m.group(1)):
                segs = [s for s in p.split("::") if s]
                if segs and segs[0] == "crate":
                    absolute = segs[1:]
                else:
                    b = list(base)
                    while segs and segs[0] in ("super", "self"):
                        if segs[0] == "super":
                            b = b[:-1]
                        segs = segs[1:]
                    absolute = b + segs
                if absolute:
                    table[absolute[-1]] = absolute
        REEXPORTS[path] = table
    return REEXPORTS[path]


def resolve(target, files, depth=0):
    """The file that defines what the path names, following re-exports."""
    f = file_of(target, files)
    if f is None or depth > 8:
        return f
    n = len(module_of(f))
    rest = target[n:]
    if rest and rest[0] in reexports(f, files):
        via = tuple(reexports(f, files)[rest[0]]) + tuple(rest[1:])
        if via != target:
            return resolve(via, files, depth + 1)
    return f


def layer_of(path):
    first = path.relative_to(SRC).parts[0].removesuffix(".rs")
    return LAYERS.index(first) if first in LAYERS else None


def sibling_of(path, siblings):
    """The child of the `siblings` layer the file belongs to (`commands/replay/mod.rs` -> replay)."""
    parts = path.relative_to(SRC).parts
    if siblings is None or len(parts) < 2 or parts[0] != siblings or parts[1] == "mod.rs":
        return None
    return parts[1].removesuffix(".rs")


def cycles(graph):
    """Strongly connected components of more than one file (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def check(crate, graph_wanted):
    global SRC, LAYERS
    folder, LAYERS, siblings = crate
    SRC = ROOT / folder
    REEXPORTS.clear()
    sources = sorted(SRC.rglob("*.rs"))
    files = {tuple(module_of(p)): p for p in sources}
    graph = {}
    for p in sources:
        text = strip_comments_and_tests(p.read_text())
        graph[p] = imports(p, text, files)
    rel = lambda p: str(p.relative_to(ROOT))
    if graph_wanted:
        for p in sources:
            print(rel(p), "->", " ".join(sorted(rel(q) for q in graph[p])))
    bad = 0
    for p in sources:
        if p.parent == SRC and p.name in ("lib.rs", "main.rs"):
            continue
        lp = layer_of(p)
        if lp is None:
            print(f"{rel(p)}: in no layer (the layers are {', '.join(LAYERS)})")
            bad += 1
            continue
        for q in sorted(graph[p]):
            lq = layer_of(q)
            if lq is not None and lq > lp:
                print(f"{rel(p)} ({LAYERS[lp]}) imports {rel(q)} ({LAYERS[lq]}), a higher layer")
                bad += 1
            a, b = sibling_of(p, siblings), sibling_of(q, siblings)
            if a and b and a != b:
                print(f"{rel(p)} ({siblings}/{a}) imports {rel(q)} ({siblings}/{b}): subcommands stay apart")
                bad += 1
    for comp in cycles(graph):
        print(f"import loop of {len(comp)} files: {' '.join(rel(p) for p in comp)}")
        bad += 1
    edges = sum(len(v) for v in graph.values())
    if bad:
        print(f"layers: {folder}: {bad} violation(s) in {len(sources)} files, {edges} imports")
    else:
        print(f"layers: {folder}: {len(sources)} files, {edges} imports, all down the layers, no loop")
    return bad


def main():
    bad = sum(check(crate, "--graph" in sys.argv) for crate in CRATES)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
