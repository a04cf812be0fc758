#!/usr/bin/env python3
"""Check README.md's module map ("## How the code is laid out") against the tree.

Usage: tools/check_module_map.py [README.md]
The map is the first ``` block after that heading. Each entry is a path token that stands at
the start of a line or after two or more spaces and ends in "/" or has a file extension
(core/, shitsukan.hpp, docs/DESIGN.md, paper_figures/<paper key>/ -- "<...>" and what follows
is dropped). Lines indented under "lib/shitsukan/" name paths inside it; the others, paths
from the repository root. Checked: every entry exists; every directory of lib/shitsukan/ and
every top-level directory git tracks (except dot-directories) is listed. Exit status 1 with
one line per problem.
"""
import os, re, subprocess, sys

from doc_block import block_after

ENTRY = re.compile(r'(?:^|(?<=\s\s))([A-Za-z0-9_.-]+(?:/[A-Za-z0-9_.<> -]*?)*?(?:/|\.[a-z]{1,4}))(?=\s|$)')


def module_map(readme):
    return block_after(readme, '## How the code is laid out', 'check_module_map')


def entries(lines):
    base, out = '', []
    for line in lines:
        if not line.strip():
            continue
        indented = line.startswith(' ')
        if not indented:
            base = ''
        for m in ENTRY.finditer(line):
            token = m.group(1).split('<')[0]
            if not token or token.startswith('.'):
                continue
            path = (base + token) if indented else token
            out.append(path)
            if not indented and token == 'lib/shitsukan/':
                base = 'lib/shitsukan/'
    return out


def main():
    readme = sys.argv[1] if len(sys.argv) > 1 else 'README.md'
    listed = entries(module_map(readme))
    problems = ['README.md lists %s, which does not exist' % p for p in listed
                if not os.path.exists(p)]
    names = {'/'.join(p.rstrip('/').split('/')[:k + 1]) for p in listed
             for k in range(p.rstrip('/').count('/') + 1)}  # a path lists its parents
    modules = sorted('lib/shitsukan/' + d for d in os.listdir('lib/shitsukan')
                     if os.path.isdir(os.path.join('lib/shitsukan', d)))
    try:
        tracked = subprocess.run(['git', 'ls-files'], stdout=subprocess.PIPE, text=True,
                                 check=True).stdout.split('\n')
        top = sorted({f.split('/')[0] for f in tracked if '/' in f and not f.startswith('.')})
    except (OSError, subprocess.CalledProcessError):
        top = sorted(d for d in os.listdir('.') if os.path.isdir(d) and not d.startswith('.')
                     and d != 'build')
    for d in modules + top:
        if d not in names:
            problems.append('README.md\'s module map does not list %s/' % d)
    for p in problems:
        print('check_module_map: ' + p)
    if not problems:
        print('check_module_map: README.md\'s module map lists %d paths, all present; all %d '
              'modules and %d top-level directories listed' % (len(listed), len(modules), len(top)))
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
