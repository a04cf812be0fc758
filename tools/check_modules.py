#!/usr/bin/env python3
"""Check the modules' #include lines against docs/DESIGN.md's dependency graph.

Usage: tools/check_modules.py [docs/DESIGN.md]
The graph is the first ``` block after "## Modules and the dependency direction": one line per
module, "name <- a, b, c" ("nothing" for none; what follows two or more spaces after the list is
a comment). Every lib/shitsukan/<module>/ file's #include "shitsukan/<other>/..." must name the
module itself, core, or a module on its line. Exit status 1 with one line per problem.
"""
import os, re, sys

from doc_block import block_after

INCLUDE = re.compile(r'^\s*#\s*include\s*"shitsukan/([A-Za-z0-9_]+)/', re.M)


def graph(design):
    allowed = {}
    for line in block_after(design, '## Modules and the dependency direction', 'check_modules'):
        m = re.match(r'^([a-z_]+)\s+<-\s+(.*)$', line)
        if not m:
            continue
        uses = re.split(r'\s{2,}|\(', m.group(2).strip())[0]
        allowed[m.group(1)] = {u.strip() for u in uses.split(',') if u.strip() != 'nothing'}
    return allowed


def main():
    design = sys.argv[1] if len(sys.argv) > 1 else 'docs/DESIGN.md'
    allowed = graph(design)
    problems, files = [], 0
    for module in sorted(os.listdir('lib/shitsukan')):
        folder = os.path.join('lib/shitsukan', module)
        if not os.path.isdir(folder):
            continue
        if module not in allowed:
            problems.append('%s: module %s is not in %s\'s graph' % (folder, module, design))
            continue
        for name in sorted(os.listdir(folder)):
            if not name.endswith(('.hpp', '.cpp', '.h', '.inl')):
                continue
            path = os.path.join(folder, name)
            files += 1
            for used in sorted(set(INCLUDE.findall(open(path, encoding='utf-8').read()))):
                if used not in allowed[module] | {module, 'core'}:
                    problems.append('%s includes shitsukan/%s/, which %s may not use (%s <- %s)'
                                    % (path, used, module, module,
                                       ', '.join(sorted(allowed[module])) or 'nothing'))
    for p in problems:
        print('check-modules: ' + p)
    if problems:
        return 1
    print('check-modules: %d files of %d modules include only what %s allows'
          % (files, len(allowed), design))
    return 0


if __name__ == '__main__':
    sys.exit(main())
