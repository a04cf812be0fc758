#!/usr/bin/env python3
"""ports/web/bundle.py — assembles the explorer page into build/web/ (run by `make web`).

  bundle.py --page ports/web/page --figures build/web/figures/index.md \
            --hosted-module build/web/hosted/shitsukan_web.js \
            --single-module build/web/single/shitsukan_web.js --out build/web

Writes
  OUT/hosted/    index.html, style.css, params.js, app.js, worker.js, panels/*.js (beside the
                 module's .js and .wasm): for a static web server.
  OUT/index.html the same page in ONE file: style, scripts and the worker (with the .wasm inside
                 its loader, -sSINGLE_FILE) inlined; it opens from disk by double-click (no
                 server: Chromium fetches no separate file for a page from file://).
  OUT/params.js  the parameter tables of every figure of the papers, read from paper_figures'
                 index.md (the "given / chosen" rows the figures record), never retyped.
  OUT/sources/   every repository file a panel names (its `source` text, its C API file, its
                 page file; a .cpp's header beside it), each as <path>.html (the text in a
                 <pre>, so a browser shows it from disk too): the panels link to them. Also in
                 OUT/hosted/sources/. A named file that does not exist stops the build.

Panels are discovered: every page/panels/*.js is included, in name order, at the line
`<!-- panels -->` of page/index.html (a panel registers itself with SK.register).
"""
import argparse
import json
import os
import re
import shutil
import sys


def figure_params(index_md):
    """{"paper/id": {"caption": ..., "rows": [[name, value, "given"|"chosen here", where]]}}"""
    figures, current = {}, None
    with open(index_md, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        m = re.match(r"^### (\S+/\S+)\s*$", line)
        if m:
            current = m.group(1)
            caption = lines[i + 2].strip() if i + 2 < len(lines) else ""
            figures[current] = {"caption": caption, "rows": []}
            continue
        if current and line.startswith("| ") and not line.startswith("| parameter") and not line.startswith("|---"):
            cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
            if len(cells) == 4 and cells[2] in ("given", "chosen here"):
                figures[current]["rows"].append(cells)
    return figures


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def script_safe(js):
    # inside <script>, only "</script" ends the element; "<\/script" means the same in JS strings
    return js.replace("</script", "<\\/script")


SOURCE_TOKEN = re.compile(r"[\w./-]+\.(?:cpp|hpp|h)\b")


def panel_sources(panels_dir, repo):
    """{panel id: [repository paths]} by the rule of SK.sourceFiles in page/app.js."""
    out = {}
    for name in sorted(os.listdir(panels_dir)):
        if not name.endswith(".js"):
            continue
        text = read(os.path.join(panels_dir, name))
        ids = re.findall(r"\bid: '([a-z0-9-]+)'", text)
        sources = re.findall(r"\bsource: '((?:[^'\\]|\\.)*)'", text)
        if len(ids) != len(sources):
            sys.exit("bundle.py: %s: %d panel ids but %d source texts" % (name, len(ids), len(sources)))
        for pid, src in zip(ids, sources):
            files, folder = [], ""
            for t in SOURCE_TOKEN.findall(src):
                if "/" in t:
                    folder = t[: t.rindex("/") + 1]
                else:
                    t = folder + t
                if t not in files:
                    files.append(t)
            key = pid.split("-")[0]
            for t in ("ports/web/api/api_%s.cpp" % key, "ports/web/page/panels/%s.js" % key):
                if t not in files:
                    files.append(t)
            for t in files:
                if not os.path.isfile(os.path.join(repo, t)):
                    sys.exit("bundle.py: panel %s names %s, which is not in the repository" % (pid, t))
            out[pid] = files
    return out


def source_page(repo, path, header):
    esc = lambda t: t.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    depth = "../" * path.count("/")
    also = ('<p>Its header (declarations and the manual): <a href="%s%s.html">%s</a></p>\n'
            % (depth, header, header)) if header else ""
    return ('<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>%s</title>\n'
            '<style>body{font:14px/1.4 system-ui,sans-serif;margin:12px 18px}pre{font:13px/1.4 '
            'ui-monospace,monospace;background:#f3f5f7;padding:8px;overflow:auto}</style></head>\n'
            '<body><h1 style="font-size:17px">%s</h1><p>shitsukan repository path <code>%s</code> '
            '(a copy made by ports/web/bundle.py with the page).</p>\n%s<pre>%s</pre></body></html>\n'
            % (esc(path), esc(path), esc(path), also, esc(read(os.path.join(repo, path)))))


def write_sources(repo, panels_dir, outs):
    files = []
    for paths in panel_sources(panels_dir, repo).values():
        for p in paths:
            if p not in files:
                files.append(p)
    for p in list(files):
        h = p[:-4] + ".hpp" if p.endswith(".cpp") else None
        if h and os.path.isfile(os.path.join(repo, h)) and h not in files:
            files.append(h)
    for out in outs:
        shutil.rmtree(os.path.join(out, "sources"), ignore_errors=True)
        for p in files:
            h = p[:-4] + ".hpp" if p.endswith(".cpp") else None
            h = h if h in files else None
            write(os.path.join(out, "sources", p + ".html"), source_page(repo, p, h))
    return len(files)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--page", required=True)
    ap.add_argument("--figures", required=True)
    ap.add_argument("--hosted-module", required=True)
    ap.add_argument("--single-module", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--repo", default=".")
    a = ap.parse_args()

    params = figure_params(a.figures)
    if not params:
        sys.exit("bundle.py: no figure parameters found in " + a.figures)
    params_js = "// Generated by ports/web/bundle.py from paper_figures' index.md: do not edit.\n" \
                "window.SK_FIGURE_PARAMS = " + json.dumps(params, ensure_ascii=False, indent=0) + ";\n"
    panels = sorted(p for p in os.listdir(os.path.join(a.page, "panels")) if p.endswith(".js"))
    html = read(os.path.join(a.page, "index.html"))
    if "<!-- panels -->" not in html:
        sys.exit("bundle.py: page/index.html has no <!-- panels --> line")

    # hosted: files side by side
    hosted = os.path.join(a.out, "hosted")
    tags = "\n".join('<script src="panels/%s"></script>' % p for p in panels)
    write(os.path.join(hosted, "index.html"), html.replace("<!-- panels -->", tags))
    for name in ("style.css", "app.js", "worker.js"):
        shutil.copyfile(os.path.join(a.page, name), os.path.join(hosted, name))
    for p in panels:
        write(os.path.join(hosted, "panels", p), read(os.path.join(a.page, "panels", p)))
    write(os.path.join(hosted, "params.js"), params_js)
    write(os.path.join(a.out, "params.js"), params_js)

    # single file: everything inline; the worker's source (module + worker.js) as text
    single = html.replace("<!-- panels -->", "\n".join(
        "<script>/* panels/%s */\n%s</script>" % (p, script_safe(read(os.path.join(a.page, "panels", p)))) for p in panels))

    def inline_script(m):
        name = m.group(1)
        src = params_js if name == "params.js" else read(os.path.join(a.page, name))
        return "<script>/* %s */\n%s</script>" % (name, script_safe(src))

    single = re.sub(r'<script src="([a-z_]+\.js)"></script>', inline_script, single)
    single = single.replace('<link rel="stylesheet" href="style.css">',
                            "<style>\n%s</style>" % read(os.path.join(a.page, "style.css")))
    worker_src = read(a.single_module) + "\n" + read(os.path.join(a.page, "worker.js"))
    single = single.replace("</body>", '<script type="text/plain" id="sk-worker-src">%s</script>\n</body>'
                            % script_safe(worker_src))
    write(os.path.join(a.out, "index.html"), single)
    sources = write_sources(a.repo, os.path.join(a.page, "panels"), [a.out, hosted])
    print("bundle.py: %s (%d bytes, one file), %s/ (hosted), %d panel files, %d figures' parameters, "
          "%d source files" % (os.path.join(a.out, "index.html"), len(single.encode("utf-8")), hosted,
                               len(panels), len(params), sources))


if __name__ == "__main__":
    main()
