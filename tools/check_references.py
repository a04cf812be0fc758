#!/usr/bin/env python3
"""Nothing in the repository cites a file or an issue outside it (`make check-references`).

Usage: tools/check_references.py [--list] [root]
A reader of a clone has this repository and the papers' bibliographic references, nothing
else: no issue tracker, no notes beside the clone. So every tracked (or new, not ignored)
text file is searched for
  - an issue reference: "issue 12", "issues 12 and 17", "Issue 17.5", "#12" (one to four
    digits standing alone; "#000000" colours, CSS colours ("#555;"), "#include" and Markdown anchors such as
    "#3-table-2" do not count);
  - a note kept outside the repository: the name of the bark model's reading notes file
    (the reasoning lives in docs/papers/hirota1998.md);
  - a path outside the repository: "../shared", "/work/", "shared/papers".
Cite the paper (key, section, equation, figure) or a file of the repository instead
(docs/papers/<key>.md, docs/DESIGN.md). Binary files and this file are skipped. Exit status
1 with one line per hit (file:line: the text); --list prints the hits and exits 0.
"""
import os, re, subprocess, sys

# Built from pieces so that this file does not match itself when it is read as text.
RULES = [
    ('issue reference', re.compile(r'\bissues?\s+#?\d+(\.\d+)?\b', re.IGNORECASE)),
    ('issue reference', re.compile(r'(?<![\w&#/"\'=])#\d{1,4}(?![\w;-])')),
    ('note outside the repository', re.compile('MODEL' + r'\.md')),
    ('path outside the repository',
     re.compile(r'\.\./+shared\b|(?<![\w.])/' + 'work' + r'/|\bshared/' + 'papers\b')),
]
SKIP_PREFIXES = ('fuzz/corpus/',)  # fuzzer inputs: bytes, not prose


def repository_files(root):
    out = subprocess.run(['git', '-C', root, 'ls-files', '-z', '--cached', '--others',
                          '--exclude-standard'], check=True, capture_output=True).stdout
    return sorted(set(p for p in out.decode().split('\0') if p))


def text_of(path):
    try:
        data = open(path, 'rb').read()
    except OSError:  # listed by git but deleted in the working tree
        return None
    if b'\0' in data[:8192]:
        return None
    try:
        return data.decode('utf-8')
    except UnicodeDecodeError:
        return None


def main(argv):
    list_only = '--list' in argv
    args = [a for a in argv if a != '--list']
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
    me = os.path.relpath(os.path.abspath(__file__), os.path.abspath(root))
    hits = []
    files = 0
    for rel in repository_files(root):
        if rel == me or rel.startswith(SKIP_PREFIXES):
            continue
        text = text_of(os.path.join(root, rel))
        if text is None:
            continue
        files += 1
        for n, line in enumerate(text.split('\n'), 1):
            for what, rule in RULES:
                if rule.search(line):
                    hits.append('%s:%d: %s: %s' % (rel, n, what, line.strip()[:160]))
                    break
    for h in hits:
        print(h)
    if hits and not list_only:
        print('check-references: %d line(s) cite an issue or a file outside the repository; '
              'cite the paper or docs/papers/<key>.md, docs/DESIGN.md instead' % len(hits))
        return 1
    print('check-references: %d text files, %d reference(s) outside the repository'
          % (files, len(hits)))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
