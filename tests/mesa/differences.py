"""The intentional-differences lists shared by agreement.py (ARB) and glsl_agreement.py (GLSL)."""
import os
import re

VERDICT_WORDS = {"accept": True, "accepted": True, "reject": False, "rejected": False}


def verdict_name(accepted):
    return "accept" if accepted else "reject"


def parse_differences(path, extensions):
    """Entries of a differences file: {relpath: (arbiter, mesa, line)}, and errors.

    An entry is a table row whose first cell holds a backquoted path (verdicts in the next two
    cells), or a list item whose first backquoted text is a path with one of `extensions` (verdicts
    given as `arbiter: accept`, `mesa: reject` anywhere in the item).
    """
    entries, errors = {}, []
    if not os.path.exists(path):
        return entries, [f"{path}: the list of intentional differences is missing"]
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        where = f"{path}:{number}"
        if stripped.startswith("|"):
            cells = [c.strip() for c in stripped.strip("|").split("|")]
            m = re.fullmatch(r"`([^`]+)`", cells[0]) if cells else None
            if not m:
                continue  # header, separator, or a row without a path
            rel = m.group(1)
            if len(cells) < 3:
                errors.append(f"{where}: row for '{rel}' needs the arbiter and mesa verdicts")
                continue
            arbiter_word, mesa_word = cells[1].strip("`*").lower(), cells[2].strip("`*").lower()
        elif stripped.startswith(("- ", "* ")):
            m = re.search(r"`([^`]+)`", stripped)
            if not m or not m.group(1).endswith(extensions):
                continue
            rel = m.group(1)
            a = re.search(r"arbiter\W+(accept(?:ed)?|reject(?:ed)?)", stripped, re.I)
            b = re.search(r"mesa\W+(accept(?:ed)?|reject(?:ed)?)", stripped, re.I)
            arbiter_word = a.group(1).lower() if a else ""
            mesa_word = b.group(1).lower() if b else ""
        else:
            continue
        if arbiter_word not in VERDICT_WORDS or mesa_word not in VERDICT_WORDS:
            errors.append(f"{where}: entry for '{rel}' needs verdicts 'accept' or 'reject' "
                          f"for arbiter and mesa")
            continue
        if VERDICT_WORDS[arbiter_word] == VERDICT_WORDS[mesa_word]:
            errors.append(f"{where}: entry for '{rel}' gives both tools the same verdict")
            continue
        if rel in entries:
            errors.append(f"{where}: '{rel}' is listed twice (first on line {entries[rel][2]})")
            continue
        entries[rel] = (VERDICT_WORDS[arbiter_word], VERDICT_WORDS[mesa_word], number)
    return entries, errors
