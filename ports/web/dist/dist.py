#!/usr/bin/env python3
"""ports/web/dist/dist.py — the classroom bundle (run by `make web-dist`).

  dist.py --web build/web --readme ports/web/dist/README.md --panels ports/web/page/panels \
          --out build/web-dist --zip build/web-dist.zip

Writes OUT/ (index.html: the one-file page, nothing to install, opens from disk or any static
host; sources/: the files the panels link to, as HTML; README.md: for teachers) and the same
folder as ZIP, under one top folder shitsukan-explorer/ (sorted, fixed dates: the same input
gives the same bytes). Stops when the teachers' README does not link every panel of the page (index.html#<id>),
or links one the page does not have.
"""
import argparse
import os
import re
import shutil
import sys
import zipfile


def main():
    ap = argparse.ArgumentParser()
    for name in ("--web", "--readme", "--panels", "--out", "--zip"):
        ap.add_argument(name, required=True)
    a = ap.parse_args()
    with open(a.readme, encoding="utf-8") as f:
        readme = f.read()
    ids = []
    for name in sorted(os.listdir(a.panels)):
        if name.endswith(".js"):
            with open(os.path.join(a.panels, name), encoding="utf-8") as f:
                ids += re.findall(r"\bid: '([a-z0-9-]+)'", f.read())
    missing = [i for i in ids if "#" + i not in readme]
    if missing:
        sys.exit("dist.py: %s names no link to panel(s) %s" % (a.readme, ", ".join(missing)))
    unknown = sorted(set(re.findall(r"index\.html#([a-z0-9-]+)", readme)) - set(ids))
    if unknown:
        sys.exit("dist.py: %s links to panel(s) the page does not have: %s" % (a.readme, ", ".join(unknown)))
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    shutil.copyfile(os.path.join(a.web, "index.html"), os.path.join(a.out, "index.html"))
    shutil.copytree(os.path.join(a.web, "sources"), os.path.join(a.out, "sources"))
    shutil.copyfile(a.readme, os.path.join(a.out, "README.md"))
    files = []
    for root, _, names in os.walk(a.out):
        for n in names:
            files.append(os.path.relpath(os.path.join(root, n), a.out))
    tmp = a.zip + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED, compresslevel=9) as z:
        for rel in sorted(files):
            info = zipfile.ZipInfo("shitsukan-explorer/" + rel.replace(os.sep, "/"), (1980, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            with open(os.path.join(a.out, rel), "rb") as f:
                z.writestr(info, f.read())
    os.replace(tmp, a.zip)
    print("dist.py: %s/ (%d files: index.html, README.md, %d sources) and %s (%d bytes); %d panels in the README"
          % (a.out, len(files), len(files) - 2, a.zip, os.path.getsize(a.zip), len(ids)))


if __name__ == "__main__":
    main()
