#!/usr/bin/env python3
"""The house's one-way order, checked from the sources (cases/README.md, "Layout"; fem/README.md).

cases/ is in parts, each including only itself and the parts below it:
    report < scene < model < runners < tools < app
and a runner includes no other runner's header (its own family, e.g. candidate and candidate_coulomb, excepted;
runners/run_scene, the runners' one entry, includes them all). fem/ is in layers, each including only itself and
the layers below it:
    base < modulus < grid < io < elasticity < linear_algebra < bodies < accuracy < contact < adhesion < tangential
fem/ includes neither analytic/ nor cases/, and analytic/ neither fem/ nor cases/. The longest include chain among the files of cases/ is at most 6 levels.
The files of a report are written by report/ (table.h: write_text, Table::write_csv): no other part of the scene
library opens an std::ofstream (the FE studies, programs of their own, write their data files themselves).

The FE studies (cases/tools/studies/) are programs of their own: nothing outside their folder includes them, and
they include the scene library's parts only where STUDIES_WITH_CASES names them (the others link fem and analytic
alone). The FE tests (tests/fem/) include no part of cases/: test_fem links fem and analytic only.
Prints every violation and exits 1 when there is one; prints the longest chain either way.
"""
import os
import re
import sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..')
ORDER = ['report', 'scene', 'model', 'runners', 'tools', 'app']
FEM_ORDER = ['base', 'modulus', 'grid', 'io', 'elasticity', 'linear_algebra', 'bodies', 'accuracy', 'contact',
             'adhesion', 'tangential']
MAX_LEVELS = 6
STUDIES = os.path.join('cases', 'tools', 'studies')
# fem3d runs the Coulomb sphere's path of the scene library (model/coulomb_sphere.h), shared with the Coulomb map.
STUDIES_WITH_CASES = {os.path.join(STUDIES, 'fem3d.cc')}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
OFSTREAM = re.compile(r'\bofstream\b')


def sources(folder):
    for base, _, files in os.walk(os.path.join(ROOT, folder)):
        for f in files:
            if f.endswith(('.h', '.cc')):
                yield os.path.relpath(os.path.join(base, f), ROOT)


def includes(path):
    with open(os.path.join(ROOT, path), encoding='utf-8', errors='replace') as f:
        return INCLUDE.findall(f.read())


def case_file(path, name):
    """The cases/ file an include names, or None (a library or system header)."""
    for candidate in (os.path.join('cases', name), os.path.normpath(os.path.join(os.path.dirname(path), name)),
                      name if name.startswith('cases/') else None):
        if candidate and os.path.isfile(os.path.join(ROOT, candidate)):
            return candidate
    return None


def stem(path):
    return os.path.splitext(os.path.basename(path))[0]


def family(a, b):
    return a == b or a.startswith(b + '_') or b.startswith(a + '_')


def main():
    problems = []
    graph = {}
    for path in sources('cases'):
        parts = path.split(os.sep)
        if len(parts) < 3 or parts[1] not in ORDER:
            if path.endswith(('.h', '.cc')) and len(parts) == 2:
                problems.append(path + ': a source file outside the parts ' + ', '.join(ORDER))
            continue
        part = parts[1]
        graph[path] = []
        for name in includes(path):
            target = case_file(path, name)
            if not target:
                continue
            graph[path].append(target)
            target_part = target.split(os.sep)[1]
            if ORDER.index(target_part) > ORDER.index(part):
                problems.append('%s (%s) includes %s (%s), a part above it' % (path, part, target, target_part))
            if (part == target_part == 'runners' and stem(path) != 'run_scene' and
                    not family(stem(path), stem(target))):
                problems.append('%s includes another runner\'s header %s' % (path, target))
    for path in graph:
        if path.split(os.sep)[1] != 'report' and not path.startswith(STUDIES + os.sep):
            with open(os.path.join(ROOT, path), encoding='utf-8', errors='replace') as f:
                if OFSTREAM.search(f.read()):
                    problems.append(path + ' writes a file with std::ofstream: the files of a report are written by report/')
    for path in sources('fem'):
        parts = path.split(os.sep)
        if len(parts) < 3 or parts[1] not in FEM_ORDER:
            if len(parts) == 2:
                problems.append(path + ': a source file outside the layers ' + ', '.join(FEM_ORDER))
            continue
        for name in includes(path):
            if name.startswith('fem/'):
                layer = name.split('/')[1]
                if layer not in FEM_ORDER:
                    problems.append('%s includes %s, which is in no layer' % (path, name))
                elif FEM_ORDER.index(layer) > FEM_ORDER.index(parts[1]):
                    problems.append('%s (%s) includes %s, a layer above it' % (path, parts[1], name))
    for path, targets in graph.items():
        for target in targets:
            in_studies = target.startswith(STUDIES + os.sep)
            if in_studies and not path.startswith(STUDIES + os.sep):
                problems.append('%s includes %s: nothing outside %s includes a study' % (path, target, STUDIES))
            if (path.startswith(STUDIES + os.sep) and not in_studies and path not in STUDIES_WITH_CASES):
                problems.append('%s includes %s: a study links fem and analytic only (or is named in '
                                'STUDIES_WITH_CASES, with its link in %s/CMakeLists.txt)' % (path, target, STUDIES))
    for path in sources(os.path.join('tests', 'fem')):
        for name in includes(path):
            target = case_file(path, name)
            if name.startswith('cases/') or (target and target.startswith('cases' + os.sep)):
                problems.append('%s includes %s: the FE tests link fem and analytic only' % (path, name))
    for library, banned in (('fem', ('analytic/', 'cases/')), ('analytic', ('fem/', 'cases/'))):
        for path in sources(library):
            for name in includes(path):
                if name.startswith(banned):
                    problems.append('%s includes %s: %s must not depend on %s' % (path, name, library, name.split('/')[0]))

    depth, chain = {}, {}

    def longest(node, seen=()):
        if node in depth:
            return depth[node]
        best, best_chain = 1, [node]
        for nxt in graph.get(node, []):
            if nxt in seen:
                problems.append('include cycle through ' + ' -> '.join(seen + (node, nxt)))
                continue
            d = longest(nxt, seen + (node,)) + 1
            if d > best:
                best, best_chain = d, [node] + chain[nxt]
        depth[node], chain[node] = best, best_chain
        return best

    top = max(graph, key=longest)
    print('longest include chain in cases/ (%d levels): %s' % (depth[top], ' -> '.join(chain[top])))
    if depth[top] > MAX_LEVELS:
        problems.append('the longest include chain has %d levels (at most %d)' % (depth[top], MAX_LEVELS))
    for p in problems:
        print('layer violation: ' + p)
    print('%d violation(s)' % len(problems))
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
