#!/usr/bin/env python3
"""ctest release.citation: CITATION.cff (Citation File Format 1.2.0) has the required keys, names
the version of CMakeLists.txt and the license of LICENSE, and cites the papers of
spec/references.md with their DOIs. Python 3 standard library only (a line-based reader of the
subset of YAML the file uses: top-level 'key: value' lines and '  - ' list items)."""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
text = open(os.path.join(root, "CITATION.cff"), encoding="utf-8").read()
problems = []


def top(key):
    m = re.search(r"^" + re.escape(key) + r":[ \t]*(.*)$", text, re.M)
    return None if m is None else m.group(1).strip().strip('"')


for key in ("cff-version", "message", "title", "authors", "version", "license", "date-released", "type",
            "references"):
    if top(key) is None:
        problems.append(f"CITATION.cff: required key '{key}' is missing")
if top("cff-version") != "1.2.0":
    problems.append(f"CITATION.cff: cff-version must be 1.2.0, got {top('cff-version')!r}")
if top("type") not in (None, "software"):
    problems.append("CITATION.cff: type must be software")
cmake = open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8").read()
m = re.search(r"project\(\s*pathref\s+VERSION\s+([0-9.]+)", cmake)
if m is None or top("version") != m.group(1):
    problems.append(f"CITATION.cff: version {top('version')!r} differs from CMakeLists.txt's {m and m.group(1)!r}")
first = open(os.path.join(root, "LICENSE"), encoding="utf-8").readline().strip()
if not (first == "MIT License" and top("license") == "MIT"):
    problems.append(f"CITATION.cff: license {top('license')!r} does not match LICENSE ({first!r})")
if not re.match(r"^\d{4}-\d{2}-\d{2}$", top("date-released") or ""):
    problems.append("CITATION.cff: date-released must be YYYY-MM-DD")
if not re.search(r"^authors:\n  - (name|family-names): \S", text, re.M):
    problems.append("CITATION.cff: authors must be a non-empty list")
changelog = os.path.join(root, "CHANGELOG.md")
if top("version") and (not os.path.exists(changelog) or
                       f"## [{top('version')}]" not in open(changelog, encoding="utf-8").read()):
    problems.append(f"CHANGELOG.md has no '## [{top('version')}]' section for the cited version")

# references: each item has type, title, authors; the papers' DOIs are those of spec/references.md
refs_text = text.split("\nreferences:\n", 1)[1] if "\nreferences:\n" in text else ""
items = re.split(r"^  - ", refs_text, flags=re.M)[1:]
for i, item in enumerate(items, 1):
    for key in ("type", "title", "authors"):
        if not re.search(r"^(    )?" + key + r":", item, re.M) and not item.startswith(key + ":"):
            problems.append(f"CITATION.cff: references item {i} has no '{key}'")
spec_refs = open(os.path.join(root, "spec", "references.md"), encoding="utf-8").read()
cited = set(re.findall(r"doi: (\S+)", refs_text))
for key in ("shi2022", "cin2021", "sensors2023"):
    row = re.search(r"^\| " + key + r" \|(.*)$", spec_refs, re.M)
    doi = row and re.search(r"doi:(10\.\S+?)[ )|.]*(?:\s|$)", row.group(1))
    if not doi:
        problems.append(f"spec/references.md: no DOI for {key}")
    elif doi.group(1).rstrip(".") not in cited:
        problems.append(f"CITATION.cff: references lack {key}'s DOI {doi.group(1)}")
if not re.search(r"title: \"Application of Improved Ant Colony Algorithm", refs_text):
    problems.append("CITATION.cff: references lack the han paper")

for p in problems:
    print(p)
print(f"release.citation: {len(items)} references; {0 if problems else 1} passed, {1 if problems else 0} failed")
sys.exit(1 if problems else 0)
