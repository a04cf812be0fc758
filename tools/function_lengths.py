#!/usr/bin/env python3
"""List the functions in lib/ longer than a limit (none over 100 lines).

Usage: tools/function_lengths.py [--limit N] [--top K] [paths...]
A function is a brace block opened at namespace level (a line that is not a namespace,
class, struct, enum or union and whose brace depth outside namespaces is 0); its length is
the number of lines from the signature's first line to the closing brace. Comments and
string literals are stripped before counting braces. Exit status 1 when any is over the limit.
"""
import os, re, sys

def strip(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i); j = n if j < 0 else j
            i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2); j = n if j < 0 else j + 2
            out.append('\n' * text.count('\n', i, j)); i = j
        elif c == '"' or c == "'":
            q = c; j = i + 1
            while j < n and text[j] != q:
                j += 2 if text[j] == '\\' else 1
            out.append(q + q); i = j + 1
        else:
            out.append(c); i += 1
    return ''.join(out)

def functions(path):
    lines = strip(open(path, encoding='utf-8', errors='replace').read()).split('\n')
    stack = []  # kinds of open braces: 'ns' or 'fn' or 'other'
    start = None; name = None; sig_start = 0; res = []
    prev_nonblank = 0
    for ln, line in enumerate(lines, 1):
        for ch in line:
            if ch == '{':
                fn_depth = sum(1 for k in stack if k != 'ns')
                if fn_depth == 0:
                    head = ' '.join(lines[max(0, sig_start - 1):ln]).strip()
                    if re.search(r'\b(namespace|extern\s+"")\b', head) and '(' not in head.split('namespace')[-1]:
                        stack.append('ns'); continue
                    if re.search(r'\b(class|struct|enum|union)\b[^()]*$', head) or '(' not in head:
                        stack.append('other'); continue
                    m = re.findall(r'([A-Za-z_~][A-Za-z_0-9:~<>]*)\s*\(', head)
                    name = m[0] if m else '?'
                    if name in ('if', 'for', 'while', 'switch', 'return'):
                        name = m[0]
                    start = sig_start; stack.append('fn')
                else:
                    stack.append('other')
            elif ch == '}':
                if not stack: continue
                k = stack.pop()
                if k == 'fn' and sum(1 for x in stack if x != 'ns') == 0:
                    res.append((ln - start + 1, name, start))
        s = line.strip()
        if sum(1 for k in stack if k != 'ns') == 0:
            if s == '' or s.endswith(';') or s.endswith('}') or s.startswith('#') or s.endswith('{'):
                sig_start = ln + 1
            elif sig_start > ln:
                pass
    return res

def main():
    args = sys.argv[1:]; limit = 100; top = 0; paths = []
    while args:
        a = args.pop(0)
        if a == '--limit': limit = int(args.pop(0))
        elif a == '--top': top = int(args.pop(0))
        else: paths.append(a)
    if not paths: paths = ['lib']
    rows = []
    for p in paths:
        for root, _, files in os.walk(p) if os.path.isdir(p) else [('', [], [p])]:
            for f in files:
                if f.endswith(('.cpp', '.hpp')):
                    fp = os.path.join(root, f)
                    rows += [(n, nm, fp, st) for n, nm, st in functions(fp)]
    rows.sort(reverse=True)
    over = [r for r in rows if r[0] > limit]
    for n, nm, fp, st in (rows[:top] if top else over):
        print(f'{n:5d}  {fp}:{st}  {nm}')
    print(f'function_lengths: {len(over)} function(s) over {limit} lines in {", ".join(paths)}')
    return 1 if over else 0

sys.exit(main())
