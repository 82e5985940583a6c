#!/usr/bin/env python3
"""Seed corpora and dictionaries for the fuzz targets in fuzz/ (see docs/robustness.md).

    python3 scripts/fuzz_seeds.py corpus MAX_LEN [DIR]   # DIR/<target>/ (default fuzz/corpus) from the shared corpus and fixtures
    python3 scripts/fuzz_seeds.py dicts            # fuzz/dict/{opendrive,openscenario}.dict from the XSDs

Seeds are written, never committed: the shared corpus (../shared/corpus beside the repository)
and the project's own fixtures are read and copied (one file per seed, named by content hash,
so running twice adds nothing). For the `xosc` target each seed bundles a scenario with the
catalog files it references and an empty stand-in for its road network, in the target's
`\\0PATH\\n` multi-file layout (fuzz/fuzz_targets/xosc.rs).
"""

import hashlib
import os
import re
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
SHARED = REPO.parent / "shared" / "corpus"
FUZZ = REPO / "fuzz"

# Where each target's seeds come from (globs, relative to REPO or SHARED).
XODR_SOURCES = [
    (SHARED, "esmini/xodr/*.xodr"),
    (SHARED, "generated/xodr/*.xodr"),
    (REPO, "crates/opendrive/tests/files/*.xodr"),
    (REPO, "crates/engine/tests/files/**/*.xodr"),
    (REPO, "crates/cli/tests/files/**/*.xodr"),
    (REPO, "examples/roads/*.xodr"),
]
XOSC_SOURCES = [
    (SHARED, "esmini/xosc/*.xosc"),
    (SHARED, "generated/xosc/*.xosc"),
    (REPO, "crates/scenario/tests/files/**/*.xosc"),
    (REPO, "crates/engine/tests/files/**/*.xosc"),
    (REPO, "crates/cli/tests/files/**/*.xosc"),
    (REPO, "examples/scenarios/*.xosc"),
]
DSL_SOURCES = [
    (REPO, "crates/dsl/**/*.osc"),
    (REPO, "examples/**/*.osc"),
]
# The OpenSCENARIO DSL excerpt whose "Code N." and "Prototype" blocks are seeds too.
DSL_EXCERPTS = sorted((REPO.parent / "shared" / "seeds").glob("000_*.txt"))

# Expressions the corpus has few of: every operator, function and literal form (§9.2).
EXPR_SEEDS = [
    "1 + 2 * 3 - 4 / 5 % 6",
    "-(2.5e3) ** 2",
    "$i * $d + $n",
    "not true and false or $b",
    "1 < 2 and 2 <= 2 and 3 > 2 and 3 >= 3 and 1 == 1 and 1 != 2",
    "round(2.5) + floor(-1.5) + ceil(1.2) + sqrt(16) + pow(2, 10)",
    "sin(0.5) + cos(0.5) + tan(0.5) + asin(0.5) + acos(0.5) + atan(0.5)",
    "atan2(1, 2) + abs(-3) + min(1, 2) + max(3, 4) + exp(1) + log(10) + log10(100)",
    "sign(-2) * trunc(3.7)",
    "((((((1))))))",
    "$s",
    "1e308 * 10",
    "9223372036854775807 + 1",
    "0.0 / 0.0",
]


def text_hash(data: bytes) -> str:
    return hashlib.sha1(data).hexdigest()[:16]


def write_seed(root: Path, target: str, data: bytes, max_len: int) -> bool:
    if len(data) > max_len or not data:
        return False
    out = root / target
    out.mkdir(parents=True, exist_ok=True)
    (out / text_hash(data)).write_bytes(data)
    return True


def files(sources):
    for base, pattern in sources:
        yield from sorted(p for p in base.glob(pattern) if p.is_file())


def norm(rel: str) -> str | None:
    """`rel` with `.` and `..` folded; None if it climbs above the root."""
    parts = []
    for c in rel.replace("\\", "/").split("/"):
        if c in ("", "."):
            continue
        if c == "..":
            if not parts:
                return None
            parts.pop()
        else:
            parts.append(c)
    return "/".join(parts)


def xosc_bundle(path: Path) -> bytes | None:
    """The scenario, the catalog files whose Catalog it references, an empty road network."""
    text = path.read_bytes()
    s = text.decode("utf-8", errors="replace")
    if "<Catalog " in s and "<Storyboard" not in s:
        return None  # a catalog file itself
    referenced = set(re.findall(r'catalogName="([^"$]+)"', s))
    parts = [text]
    for written in re.findall(r'<Directory\s+path="([^"$]+)"', s):
        d = (path.parent / written).resolve()
        if not d.is_dir():
            continue
        for f in sorted(d.glob("*.xosc")):
            ftext = f.read_bytes()
            m = re.search(rb'<Catalog\s+name="([^"]+)"', ftext)
            if m and m.group(1).decode("utf-8", "replace") in referenced:
                rel = norm("xosc/" + os.path.relpath(f, path.parent))
                if rel:
                    parts.append(b"\0" + rel.encode() + b"\n" + ftext)
    for written in re.findall(r'<(?:LogicFile|ScenarioFile)\s+filepath="([^"$]+)"', s):
        rel = norm("xosc/" + written)
        if rel:
            parts.append(b"\0" + rel.encode() + b"\n")
    return b"".join(parts)


def dsl_blocks(text: str):
    """The code under each "Code N." or "Prototype" line of a standard excerpt, up to the next
    section number, caption or blank line followed by unindented prose."""
    block = None
    for line in text.splitlines():
        if line.startswith("Code ") or line.strip() == "Prototype":
            if block:
                yield "\n".join(block).strip() + "\n"
            block = []
            continue
        if block is None:
            continue
        if re.match(r"^\d+(\.\d+)+ ", line) or line.startswith(("Table ", "Parameter Type")):
            if block:
                yield "\n".join(block).strip() + "\n"
            block = None
            continue
        block.append(line)
    if block:
        yield "\n".join(block).strip() + "\n"


def corpus(max_len: int, root: Path) -> None:
    counts = {}

    def add(target, data):
        if write_seed(root, target, data, max_len):
            counts[target] = counts.get(target, 0) + 1

    for f in files(XODR_SOURCES):
        add("opendrive", f.read_bytes())
    exprs = set(EXPR_SEEDS)
    for f in files(XOSC_SOURCES):
        data = f.read_bytes()
        text = data.decode("utf-8", errors="replace")
        if "ParameterValueDistribution" in text:
            add("distribution", data)
        bundle = xosc_bundle(f)
        if bundle:
            add("xosc", bundle)
        exprs.update(re.findall(r"\$\{([^}]*)\}", text))
    for e in sorted(exprs):
        add("expr", e.encode())
    for f in files(DSL_SOURCES):
        add("dsl", f.read_bytes())
    for f in DSL_EXCERPTS:
        for block in dsl_blocks(f.read_text(encoding="utf-8", errors="replace")):
            add("dsl", block.encode())
    for target, n in sorted(counts.items()):
        print(f"{target}: {n} seeds")


def xsd_names(folder: Path):
    elements, attributes, values = set(), set(), set()
    for xsd in sorted(folder.glob("*.xsd")):
        s = xsd.read_text(encoding="utf-8", errors="replace")
        elements.update(re.findall(r'<xsd?:element\s+name="([A-Za-z]+)"', s))
        attributes.update(re.findall(r'<xsd?:attribute\s+name="([A-Za-z]+)"', s))
        values.update(re.findall(r'<xsd?:enumeration\s+value="([^"]+)"', s))
    return elements, attributes, values


def dicts() -> None:
    schemas = {
        "openscenario": SHARED / "schema/openscenario/1.3.0",
        "opendrive": SHARED / "schema/opendrive/1.8.0",
    }
    for name, folder in schemas.items():
        elements, attributes, values = xsd_names(folder)
        lines = [
            f"# libFuzzer dictionary: {name} element and attribute names and enumeration values,",
            f"# from the XSDs in shared/corpus/schema (scripts/fuzz_seeds.py dicts).",
            '"<?xml version=\\"1.0\\" encoding=\\"UTF-8\\"?>"',
            '"</"',
            '"/>"',
            '"=\\""',
            '"<!--"',
            '"-->"',
            '"<![CDATA["',
            '"&amp;"',
            '"${"',
            '"$"',
        ]
        lines += sorted(f'"<{e}"' for e in elements)
        lines += sorted(f'" {a}=\\""' for a in attributes)
        lines += sorted(f'"\\"{v}\\""' for v in values if '"' not in v and "\\" not in v)
        out = FUZZ / "dict" / f"{name}.dict"
        out.write_text("\n".join(lines) + "\n")
        print(f"{out.relative_to(REPO)}: {len(lines)} entries")


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "corpus":
        corpus(
            int(sys.argv[2]) if len(sys.argv) > 2 else 65536,
            Path(sys.argv[3]) if len(sys.argv) > 3 else FUZZ / "corpus",
        )
    elif len(sys.argv) >= 2 and sys.argv[1] == "dicts":
        dicts()
    else:
        sys.exit(__doc__)
