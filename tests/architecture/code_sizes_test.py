#!/usr/bin/env python3
"""No file in lab/ over 600 lines, no function over 80.

A function is a brace block at namespace or class level whose head (the text since the previous
';', '{' or '}' at that level) ends in ')' and optional qualifiers (const, noexcept, override,
a trailing return type, a constructor's initializers), or is a lambda or an initializer at
namespace level; its length counts from the line of its head's name to its closing brace.
Comments, strings and character literals are blanked first, so braces in them do not count.

    code_sizes_test.py <repository root> [--list N]   (--list: the N longest functions, and pass)
"""
import pathlib
import re
import sys

MAX_FILE_LINES = 600
MAX_FUNCTION_LINES = 80


def blank(text):
    """Comments, strings and character literals replaced by spaces (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == '_')):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(')' + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif c in '"\'':
            if c == "'" and i > 0 and text[i - 1].isalnum():  # a digit separator: 1'000
                out.append(' '); i += 1; continue
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            j = min(j + 1, n)
            out.append(' ' * (j - i)); i = j
        else:
            out.append(c); i += 1
    return ''.join(out)


HEAD_END = re.compile(r'\)\s*(const|noexcept|override|final|mutable|->[^;{}]*|\s)*$')
NOT_FUNCTION = re.compile(r'\b(namespace|class|struct|union|enum|extern)\b[^()]*$')


def functions(text):
    """(name, first line, last line) of each function body at namespace or class level."""
    code = blank(text)
    found = []
    stack = []  # for each open brace: True when it opens a function body (or is inside one)
    head_start = 0
    for i, c in enumerate(code):
        if c == '{':
            inside = bool(stack and stack[-1])
            head = code[head_start:i]
            is_function = False
            if not inside:
                h = head.strip()
                init = re.search(r'\)\s*:\s*[\w:]+\s*[({]', h)  # a constructor's initializers
                if (HEAD_END.search(h) or init) and not NOT_FUNCTION.search(h) and not h.startswith('='):
                    is_function = True
                    m = re.search(r'([~\w:]+(?:operator\s*\S+)?)\s*\(', h)
                    name = m.group(1) if m else '?'
                    first = code.count('\n', 0, head_start + (len(head) - len(head.lstrip()))) + 1
                    stack.append(('fn', name, first))
                    continue
            stack.append(True if inside else False)
            if not inside:
                head_start = i + 1
        elif c == '}':
            top = stack.pop() if stack else False
            if isinstance(top, tuple):
                found.append((top[1], top[2], code.count('\n', 0, i) + 1))
            if not (stack and stack[-1]):
                head_start = i + 1
        elif c == ';' and not (stack and stack[-1]):
            head_start = i + 1
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.').resolve()
    listing = int(sys.argv[sys.argv.index('--list') + 1]) if '--list' in sys.argv else 0
    problems, every = [], []
    files = sorted(p for p in (root / 'lab').rglob('*') if p.suffix in ('.cpp', '.h'))
    for path in files:
        rel = path.relative_to(root).as_posix()
        text = path.read_text(encoding='utf-8')
        lines = text.count('\n') + (0 if text.endswith('\n') else 1)
        if lines > MAX_FILE_LINES:
            problems.append(f'{rel}: {lines} lines (at most {MAX_FILE_LINES})')
        for name, first, last in functions(text):
            length = last - first + 1
            every.append((length, f'{rel}:{first}', name))
            if length > MAX_FUNCTION_LINES:
                problems.append(f'{rel}:{first}: {name} is {length} lines (at most {MAX_FUNCTION_LINES})')
    every.sort(reverse=True)
    for length, where, name in every[:listing]:
        print(f'{length:4d} {name} {where}')
    for p in problems:
        print(p)
    longest = max(files, key=lambda p: p.read_text(encoding='utf-8').count('\n'))
    print(f'{len(files)} files, {len(every)} functions; longest function {every[0][0] if every else 0} lines; '
          f'longest file {longest.relative_to(root).as_posix()}; {len(problems)} over the limits')
    sys.exit(1 if problems and not listing else 0)


main()
