#!/usr/bin/env python3
"""No function longer than about 120 lines (STYLE.md: a function reads as one step).

Scans the C++ sources of analytic/, fem/, cases/ and numerics/ and counts the lines of every function body: from the line of its opening
brace to the line of its closing one. A body is a brace whose statement so far (since the last ';', '{' or '}')
holds a parameter list and is not a control statement, a namespace, a class, an enum or a lambda inside another
body; lambdas and local classes count toward the function that holds them. Comments and string literals are
blanked first, so a brace in them does not count.

Prints the longest bodies and every one above the limit as file:line: name (lines); exits 1 when one is above.

    function_lengths.py [ROOT] [--limit N] [--top N]
    function_lengths.py --self-test   (the count on a made-up source whose lengths are known)
"""
import argparse
import os
import re
import sys

FOLDERS = ('analytic', 'fem', 'cases', 'numerics')
CONTROL = re.compile(r'^\s*(?:if|for|while|switch|catch|else|do|try)\b|^\s*(?:namespace|class|struct|enum|union)\b')
NAME = re.compile(r'([~\w:<>]+)\s*\(')


def blank(text):
    """The source with comments and string or character literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        two = text[i:i + 2]
        if two == '//':
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i))
            i = j
        elif two == '/*':
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif text.startswith('R"(', i):
            j = text.find(')"', i + 3)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif text[i] in '"\'':
            quote, j = text[i], i + 1
            while j < n and text[j] != quote:
                j += 2 if text[j] == '\\' else 1
            out.append(' ' * (min(j, n - 1) + 1 - i))
            i = j + 1
        else:
            out.append(text[i])
            i += 1
    return ''.join(out)


def bodies(path):
    """(line, name, length) of every function body in `path`."""
    with open(path, encoding='utf-8', errors='replace') as f:
        code = blank(f.read())
    found, stack, statement, line = [], [], '', 1
    for c in code:
        if c == '\n':
            line += 1
        if c == '{':
            inside = any(kind == 'function' for kind, _, _ in stack)
            head = statement.strip()
            is_function = (not inside and '(' in head and not CONTROL.search(head) and not head.endswith('=')
                           and not re.search(r'\]\s*\([^)]*\)[^(]*$', head))
            names = NAME.findall(head) if is_function else []
            stack.append(('function' if is_function else 'block', line, names[0] if names else ''))
            statement = ''
        elif c == '}':
            if stack:
                kind, start, name = stack.pop()
                if kind == 'function':
                    found.append((start, name, line - start + 1))
            statement = ''
        elif c == ';':
            statement = ''
        else:
            statement += c
    return found


def self_test():
    """The count on a made-up source: a long function with a lambda, a class with an inline member, a string and
    a comment holding braces, control blocks; returns 0 when every length is what it must be."""
    import tempfile
    long_body = ''.join(f'  x += {i};\n' for i in range(118))
    source = ('namespace n\n{\n'
              'int long_one(int x)\n{\n  const auto f = [](int y) { return y; };\n' + long_body + '  return f(x);\n}\n'
              'struct S\n{\n  int get() const { return 1; }\n  int v = 0;\n};\n'
              'void braces()\n{\n  const char *t = "{{{"; // }}}\n  if (t)\n  {\n  }\n}\n}\n')
    with tempfile.NamedTemporaryFile('w', suffix='.cc', delete=False) as f:
        f.write(source)
    found = {name: length for _, name, length in bodies(f.name)}
    os.unlink(f.name)
    want = {'long_one': 122, 'get': 1, 'braces': 6}
    if found != want:
        print(f'self-test failed: found {found}, want {want}')
        return 1
    print('self-test passed')
    return 0


def main():
    if '--self-test' in sys.argv:
        return self_test()
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('root', nargs='?', default=os.path.join(os.path.dirname(__file__), '..'))
    parser.add_argument('--limit', type=int, default=120)
    parser.add_argument('--top', type=int, default=5)
    args = parser.parse_args()
    rows = []
    for folder in FOLDERS:
        for base, _, files in sorted(os.walk(os.path.join(args.root, folder))):
            for f in sorted(files):
                if f.endswith(('.h', '.cc')):
                    path = os.path.join(base, f)
                    rows += [(length, os.path.relpath(path, args.root), start, name)
                             for start, name, length in bodies(path)]
    rows.sort(reverse=True)
    over = [r for r in rows if r[0] > args.limit]
    for length, path, start, name in rows[:max(args.top, len(over))]:
        print(f'{path}:{start}: {name} ({length} lines){"  above the limit" if length > args.limit else ""}')
    print(f'{len(rows)} function bodies in {", ".join(FOLDERS)}; {len(over)} above {args.limit} lines')
    return 1 if over else 0


if __name__ == '__main__':
    sys.exit(main())
