#!/usr/bin/env python3
"""docs/gallery.md shows every effect of corpus/exec/gallery: each effect has an ARB and a
GLSL shader test with the same [test] section, and the page shows both pictures, which exist
in docs/gallery/ and are what `arbiter run --png` draws now (softpipe through OSMesa); the ARB
pair's GLSL 3.30 core translation (`--translate=glsl330`, state as uniforms) passes too and
draws the pictures of docs/gallery/glsl330/.

  gallery_doc_test.py ARBITER SOURCE_DIR
"""
import filecmp
import os
import subprocess
import sys
import tempfile


def test_section(path):
    text = open(path).read()
    return text[text.index("\n[test]\n"):]


def main():
    arbiter, root = os.path.abspath(sys.argv[1]), sys.argv[2]
    corpus = os.path.join(root, "corpus", "exec", "gallery")
    page = open(os.path.join(root, "docs", "gallery.md")).read()
    effects = sorted({f.rsplit("-", 1)[0] for f in os.listdir(corpus)
                      if f.endswith(".shader_test")})
    failures = []
    for effect in effects:
        arb = os.path.join(corpus, f"{effect}-arb.shader_test")
        glsl = os.path.join(corpus, f"{effect}-glsl.shader_test")
        if not (os.path.exists(arb) and os.path.exists(glsl)):
            failures.append(f"{effect}: needs both -arb and -glsl files")
            continue
        if test_section(arb) != test_section(glsl):
            failures.append(f"{effect}: the [test] sections of the two files differ")
        for picture in (f"{effect}-arb", f"{effect}-glsl", f"glsl330/{effect}-arb"):
            if f"(gallery/{picture}.png)" not in page:
                failures.append(f"{effect}: docs/gallery.md does not show {picture}.png")
    # (run options, folder under docs/gallery, the pictures kept)
    for options, folder, suffix in (([], "", ".png"),
                                    (["--translate=glsl330"], "glsl330", "-arb.png")):
        with tempfile.TemporaryDirectory() as tmp:
            p = subprocess.run([arbiter, "run", *options, "--png", tmp, corpus],
                               capture_output=True, text=True, timeout=600)
            if p.returncode != 0:
                failures.append(f"the gallery does not pass {options}:\n" + p.stdout)
            for name in sorted(n for n in os.listdir(tmp) if n.endswith(suffix)):
                kept = os.path.join(root, "docs", "gallery", folder, name)
                if not os.path.exists(kept) or not filecmp.cmp(os.path.join(tmp, name), kept,
                                                               shallow=False):
                    failures.append(f"docs/gallery/{os.path.join(folder, name)} is not what "
                                    f"arbiter run {' '.join(options)} draws now "
                                    f"(regenerate: docs/gallery.md)")
    for f in failures:
        print("FAILED", f)
    print(f"gallery_doc_test: {len(effects)} effects, {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
