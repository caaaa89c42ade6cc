#!/usr/bin/env python3
"""List C/C++ functions longer than N lines; exit 1 when any is found (a CI gate for "no function over 150 lines").

usage: scripts/long_functions.py [--max N] [--exclude SUBSTRING ...] [PATH ...]

PATHs are files or directories (searched for .c .cc .cpp .cxx .h .hh .hpp .hxx .ipp). With no PATH the project's
code is scanned: lib ports host_sim bench, without tests and generated headers. Output, longest first:

  path:line: name: N lines

A function is a '{' whose preceding code ends with ')' plus optional qualifiers (const, noexcept, override, final,
'-> type', a constructor's member initialisers, ...) and is not a control statement (if/for/while/switch/catch) or
a lambda. Lambdas and local classes count as part of the function around them. The scan skips comments, string and
character literals (raw strings included) and preprocessor lines; it is a heuristic, not a parser.
"""

import argparse
import os
import re
import sys

SOURCE_EXTENSIONS = (".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".hxx", ".ipp")
DEFAULT_ROOTS = ("lib", "ports", "host_sim", "bench")
# Generated code is not written by hand, so it is not held to the habit.
DEFAULT_EXCLUDES = ("/generated/", "_generated.", ".generated.")

CONTROL_KEYWORDS = {"if", "for", "while", "switch", "catch", "return", "sizeof", "alignof", "decltype",
                    "static_assert", "noexcept", "alignas", "throw", "new", "delete", "co_return", "co_await"}
# Words that may sit between a function's ')' and its '{'.
TRAILING_QUALIFIERS = {"const", "volatile", "noexcept", "override", "final", "mutable", "constexpr", "try"}

IDENT = r"[A-Za-z_~][A-Za-z0-9_]*"


def blank_comments_and_literals(text):
  """Same text with comments, literals and preprocessor lines replaced by spaces (newlines kept, so lines match)."""
  out = []
  i, n = 0, len(text)
  at_line_start = True
  while i < n:
    c = text[i]
    if c == "\n":
      out.append(c)
      i += 1
      at_line_start = True
      continue
    if at_line_start and c in " \t":
      out.append(c)
      i += 1
      continue
    if at_line_start and c == "#":
      # Preprocessor line, with backslash continuations.
      while i < n and text[i] != "\n":
        if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
          out.append(" \n")
          i += 2
          continue
        out.append(" ")
        i += 1
      continue
    at_line_start = False
    if text.startswith("//", i):
      while i < n and text[i] != "\n":
        out.append(" ")
        i += 1
      continue
    if text.startswith("/*", i):
      end = text.find("*/", i + 2)
      end = n if end < 0 else end + 2
      out.append(re.sub(r"[^\n]", " ", text[i:end]))
      i = end
      continue
    raw = re.match(r'(?:u8|u|U|L)?R"([^()\\ \t\n]{0,16})\(', text[i:i + 24])
    if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
      close = ")" + raw.group(1) + '"'
      end = text.find(close, i + raw.end())
      end = n if end < 0 else end + len(close)
      out.append(re.sub(r"[^\n]", " ", text[i:end]))
      i = end
      continue
    token = re.search(r"[A-Za-z0-9_.]+$", text[max(0, i - 64):i]) if c == "'" else None
    if token and token.group(0)[0].isdigit():
      # Digit separator (1'000'000), not a character literal.
      out.append(" ")
      i += 1
      continue
    if c in "\"'":
      j = i + 1
      while j < n and text[j] != c and text[j] != "\n":
        j += 2 if text[j] == "\\" else 1
      j = min(j + 1, n)
      out.append(re.sub(r"[^\n]", " ", text[i:j]))
      i = j
      continue
    out.append(c)
    i += 1
  return "".join(out)


def matching_open_paren(code, close):
  """Index of the '(' that the ')' at `close` closes, or -1."""
  depth = 0
  for k in range(close, -1, -1):
    if code[k] == ")":
      depth += 1
    elif code[k] == "(":
      depth -= 1
      if depth == 0:
        return k
  return -1


def strip_trailing_qualifiers(code, end):
  """Index just past the ')' that ends a function's declarator, looking back from `end` (the '{'), or -1."""
  k = end
  while True:
    s = code[:k].rstrip()
    k = len(s)
    if not s:
      return -1
    if s.endswith(")"):
      return k
    word = re.search(IDENT + r"$", s)
    if word and word.group(0) in TRAILING_QUALIFIERS:
      k = word.start()
      continue
    if s.endswith("&&") or s.endswith("&"):
      k -= 2 if s.endswith("&&") else 1
      continue
    # Trailing return type "-> T" (T may be qualified or templated): step back to the arrow.
    arrow = s.rfind("->")
    if arrow >= 0 and re.fullmatch(r"\s*[A-Za-z0-9_:<>,*&\s]+", s[arrow + 2:]):
      k = arrow
      continue
    return -1


def skip_member_initialisers(code, k):
  """For a constructor 'X(...) noexcept : a_(x), b_{y} {', the index just before its ':'; else `k`."""
  # Walk back over "name(args)" / "name{args}" items separated by commas until a lone ':' is found.
  j = k
  while True:
    close = j - 1
    if close < 0 or code[close] not in ")}":
      return k
    opener = "(" if code[close] == ")" else "{"
    depth = 0
    m = close
    while m >= 0:
      if code[m] in ")}":
        depth += 1
      elif code[m] in "({":
        depth -= 1
        if depth == 0:
          break
      m -= 1
    if m < 0 or code[m] != opener:
      return k
    name = re.search(r"(" + IDENT + r"(?:::" + IDENT + r")*(?:<[^;{}()]*>)?)\s*$", code[:m])
    if not name:
      return k
    before = code[:name.start()].rstrip()
    if before.endswith(","):
      j = len(before) - 1
      j = len(code[:j].rstrip())
      continue
    if before.endswith(":") and not before.endswith("::"):
      return len(code[:len(before) - 1].rstrip())
    return k


def function_name(code, brace):
  """The name of the function whose body opens at `brace`, or None when that '{' is not a function body."""
  k = skip_member_initialisers(code, len(code[:brace].rstrip()))
  k = strip_trailing_qualifiers(code, k)
  if k < 0:
    return None
  open_paren = matching_open_paren(code, k - 1)
  if open_paren < 0:
    return None
  head = code[:open_paren].rstrip()
  if head.endswith("]") or head.endswith(">") and re.search(r"\]\s*<[^>]*>$", head):
    return None  # lambda: [captures](params) {
  name = re.search(r"(operator\s*(?:\(\)|[^\s(]+)|" + IDENT + r"(?:\s*::\s*~?" + IDENT + r")*)\s*$", head)
  if not name:
    return None
  text = re.sub(r"\s+", "", name.group(1))
  if text.split("::")[-1] in CONTROL_KEYWORDS:
    return None
  # "Foo x(a, b) {" cannot occur; but "= f(x) {" or "return g(y) {" are not bodies either.
  before = code[:name.start()].rstrip()
  if before.endswith("=") or before.endswith("(") or before.endswith(","):
    return None
  return text


def long_functions(path, max_lines):
  """(line, name, lines) of each outermost function body in `path` longer than max_lines."""
  with open(path, encoding="utf-8", errors="replace") as f:
    code = blank_comments_and_literals(f.read())
  found = []
  stack = []  # per open brace: (index, function name or None)
  inside_function = 0
  line_of = None
  for i, c in enumerate(code):
    if c == "{":
      name = None if inside_function else function_name(code, i)
      stack.append((i, name))
      if name:
        inside_function += 1
    elif c == "}" and stack:
      start, name = stack.pop()
      if name:
        inside_function -= 1
        if line_of is None:
          line_of = line_index(code)
        first, last = line_at(line_of, start), line_at(line_of, i)
        lines = last - first + 1
        if lines > max_lines:
          found.append((first, name, lines))
  return found


def line_index(code):
  return [m.start() for m in re.finditer("\n", code)]


def line_at(newlines, pos):
  """1-based line number of character `pos`."""
  lo, hi = 0, len(newlines)
  while lo < hi:
    mid = (lo + hi) // 2
    if newlines[mid] < pos:
      lo = mid + 1
    else:
      hi = mid
  return lo + 1


def source_files(paths, excludes):
  for root in paths:
    if os.path.isfile(root):
      candidates = [root]
    else:
      candidates = []
      for directory, subdirs, files in os.walk(root):
        subdirs[:] = sorted(d for d in subdirs if not d.startswith(".") and not d.startswith("build"))
        candidates += [os.path.join(directory, f) for f in sorted(files)]
    for path in candidates:
      if path.endswith(SOURCE_EXTENSIONS) and not any(e in path.replace(os.sep, "/") for e in excludes):
        yield path


def main(argv):
  parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
  parser.add_argument("paths", nargs="*", help="files or directories (default: %s)" % " ".join(DEFAULT_ROOTS))
  parser.add_argument("--max", type=int, default=150, help="longest allowed function, in lines (default 150)")
  parser.add_argument("--exclude", action="append", default=list(DEFAULT_EXCLUDES),
                      help="skip paths containing this text (repeatable; generated code is skipped already)")
  args = parser.parse_args(argv)
  paths = args.paths
  if not paths:
    top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    paths = [os.path.relpath(os.path.join(top, r)) for r in DEFAULT_ROOTS if os.path.isdir(os.path.join(top, r))]
  results = []
  for path in source_files(paths, args.exclude):
    results += [(lines, path, line, name) for line, name, lines in long_functions(path, args.max)]
  results.sort(key=lambda r: (-r[0], r[1], r[2]))
  for lines, path, line, name in results:
    print("%s:%d: %s: %d lines" % (path, line, name, lines))
  return 1 if results else 0


if __name__ == "__main__":
  sys.exit(main(sys.argv[1:]))
