#!/usr/bin/env python3
"""Public edges that cannot be called wrongly: required outputs are references.

Usage: tools/check_output_params.py [--list]
Reads every public header (lib/shitsukan/**/*.hpp) and finds the functions that return a
Status (free functions, members, friends). Every non-const object pointer parameter
(not void*, not a function pointer) must be one of
  - optional: its default is nullptr (the header documents what null means),
  - a buffer: the next parameter is its size (capacity, count, size, bytes, *_capacity, ...),
  - listed in POINTERS_KEPT below with the reason (arrays whose length other arguments give,
    pointers documented as "may be null"),
  - or in a module of NOT_YET_CONVERTED.
Every other one should be a reference (T& out): the caller cannot pass null, and the
function need not check. Exit status 1 with one line per offending parameter; --list prints
every output pointer found, allowed or not, with the reason.
"""
import glob, re, sys

# Modules whose required outputs are still pointers: none (geom/ and leather/ were the last,
# converted after the Voronoi line merged). A module listed here is skipped.
NOT_YET_CONVERTED = set()

# Pointers kept on purpose, by (function, parameter): arrays written element by element whose
# length other arguments give, and pointers the header documents as optional.
POINTERS_KEPT = {
    ('height_map_normals', 'out'): 'array of width·height normals',
    ('connection_areas', 'area'): 'array of node_count areas',
    ('connection_areas', 'face'): 'array of spring_count face lengths',
    ('mesh_texture_tangents', 'dpdx'): 'array of triangle_count tangents (capacity follows dpdy)',
    ('relax', 'touched'): 'optional: "may be null" (bark/spring_network.hpp)',
    ('rasterize_scale_labels', 'labels'): 'array of width·height labels',
    ('make_box_arrays', 'positions'): 'caller array of vertex_capacity positions (mesh_arrays.hpp)',
    ('make_box_arrays', 'normals'): 'caller array of vertex_capacity normals (mesh_arrays.hpp)',
    ('make_uv_sphere_arrays', 'positions'): 'caller array of vertex_capacity positions (mesh_arrays.hpp)',
    ('make_uv_sphere_arrays', 'normals'): 'caller array of vertex_capacity normals (mesh_arrays.hpp)',
    ('make_cylinder_arrays', 'positions'): 'caller array of vertex_capacity positions (mesh_arrays.hpp)',
    ('make_cylinder_arrays', 'normals'): 'caller array of vertex_capacity normals (mesh_arrays.hpp)',
    ('make_torus_arrays', 'positions'): 'caller array of vertex_capacity positions (mesh_arrays.hpp)',
    ('make_torus_arrays', 'normals'): 'caller array of vertex_capacity normals (mesh_arrays.hpp)',
    ('make_revolution_arrays', 'positions'): 'caller array of vertex_capacity positions (mesh_arrays.hpp)',
    ('make_revolution_arrays', 'normals'): 'caller array of vertex_capacity normals (mesh_arrays.hpp)',
}

SIZE_NAME = re.compile(r'^(\w*capacity|count|size|bytes|\w+_size|\w+_count|\w+_bytes)$')
DECL = re.compile(r'(?:^|[\s;{}])(?:friend\s+|static\s+|inline\s+)*Status\s+(\w+)\s*\(')


def strip_comments(text):
    text = re.sub(r'/\*.*?\*/', lambda m: ' ' * len(m.group(0)), text, flags=re.S)
    return re.sub(r'//[^\n]*', lambda m: ' ' * len(m.group(0)), text)


def parameters(text, start):
    """The top-level parameters of the list opening at text[start - 1] == '('."""
    depth, current, params, i = 0, '', [], start
    while i < len(text):
        c = text[i]
        if c in '([{<':
            depth += 1
        elif c in ')]}>':
            if depth == 0:
                params.append(current)
                return [' '.join(p.split()) for p in params if p.strip()]
            depth -= 1
        if c == ',' and depth == 0:
            params.append(current)
            current = ''
        else:
            current += c
        i += 1
    return []


def split(param):
    """(type, name, default) of one parameter."""
    decl, _, default = param.partition('=')
    m = re.match(r'^(.*?)(\w+)\s*(\[\s*\w*\s*\])?$', decl.strip())
    if not m or not m.group(1).strip():
        return decl.strip(), '', default.strip()
    return m.group(1).strip(), m.group(2), default.strip()


def output_pointers(path):
    text = strip_comments(open(path, encoding='utf-8').read())
    for m in DECL.finditer(text):
        params = parameters(text, m.end())
        for k, param in enumerate(params):
            type_, name, default = split(param)
            if (not type_.endswith('*') or type_.endswith('**') or '(' in param or
                    re.match(r'^(const\b|void\s*\*)', type_)):
                continue
            line = text.count('\n', 0, m.start()) + 1
            after = split(params[k + 1])[1] if k + 1 < len(params) else ''
            if default == 'nullptr':
                why = 'optional (default nullptr)'
            elif SIZE_NAME.match(after):
                why = 'buffer (size in %s)' % after
            elif (m.group(1), name) in POINTERS_KEPT:
                why = 'kept: ' + POINTERS_KEPT[(m.group(1), name)]
            elif path.split('/')[2] in NOT_YET_CONVERTED:
                why = 'module not converted yet'
            else:
                why = None
            yield '%s:%d: %s(... %s ...)' % (path, line, m.group(1), param), why


def main():
    listing = '--list' in sys.argv[1:]
    bad = 0
    for path in sorted(glob.glob('lib/shitsukan/**/*.hpp', recursive=True)):
        for where, why in output_pointers(path):
            if why is None:
                bad += 1
                print('%s: a required pointer; make it a reference (or list why in '
                      'POINTERS_KEPT)' % where)
            elif listing:
                print('%s: allowed, %s' % (where, why))
    if bad:
        print('check_output_params: %d required pointer(s) in converted modules' % bad)
        return 1
    print('check_output_params: required outputs are references in every module%s' %
          (' but ' + ', '.join(sorted(NOT_YET_CONVERTED)) if NOT_YET_CONVERTED else ''))
    return 0


if __name__ == '__main__':
    sys.exit(main())
