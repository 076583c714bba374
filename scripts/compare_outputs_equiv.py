"""Are two masked outputs the same up to the printed form of GiNaC expressions?

Usage: equiv.py OLD NEW. Lines the two files share (difflib) are the same; every other line of
OLD must pair with a distinct other line of NEW that has the same text outside its expressions
and, expression by expression, the same value at two pseudo-random rational points (variables,
and cos/sin/cot as uninterpreted functions, drawn from a hash of their names: the same on both
sides). A condition `p = 0` (and the "polynomial" of an exceptional set in JSON) may also be
printed as `-p = 0`. Exit 0 and print the number of such lines if so, exit 1 otherwise.
"""
import difflib
import hashlib
import re
import sys
from fractions import Fraction


class ParseError(Exception):
    pass


def draw(key, point):
    """A rational in [1, 8) drawn from (key, point): the same for both files."""
    h = int.from_bytes(hashlib.sha256(f"{point}:{key}".encode()).digest()[:8], "big")
    return Fraction(h % 7919 + 1000, 1000 + (h >> 20) % 997)


TOKEN = re.compile(r"""\s*(?:
    (?P<num>\d+(?:\.\d+)?)
  | (?P<cmd>\\[A-Za-z]+)
  | (?P<name>[A-Za-z][A-Za-z0-9]*)
  | (?P<op>[-+*/^(){}\[\]|_,=])
  | (?P<bad>\S))""", re.X)
FUNCTIONS = {"\\cos", "\\sin", "\\cot", "\\tan", "cos", "sin", "cot", "tan", "abs"}
MULTIPLY = {"\\times", "\\cdot"}


class Parser:
    """Recursive descent over GiNaC's text and LaTeX printers (juxtaposition multiplies)."""

    def __init__(self, text, point):
        self.toks = []
        for m in TOKEN.finditer(text):
            kind = m.lastgroup
            if kind == "bad":
                raise ParseError(m.group(kind))
            self.toks.append((kind, m.group(kind)))
        self.i = 0
        self.point = point

    def peek(self, k=0):
        return self.toks[self.i + k] if self.i + k < len(self.toks) else (None, None)

    def take(self, value=None):
        tok = self.peek()
        if tok[0] is None or (value is not None and tok[1] != value):
            raise ParseError(f"expected {value}, got {tok[1]}")
        self.i += 1
        return tok

    def parse(self):
        v = self.sum()
        if self.i != len(self.toks):
            raise ParseError(f"trailing {self.peek()[1]}")
        return v

    def sum(self):
        sign = 1
        while self.peek()[1] in ("+", "-"):
            sign = -sign if self.take()[1] == "-" else sign
        v = sign * self.product()
        while self.peek()[1] in ("+", "-"):
            op = self.take()[1]
            t = self.product()
            v = v + t if op == "+" else v - t
        return v

    def starts_factor(self):
        kind, val = self.peek()
        return kind in ("num", "name") or (kind == "cmd" and val not in MULTIPLY) or val in ("(", "{")

    def product(self):
        v = self.power()
        while True:
            kind, val = self.peek()
            if val == "*" or val in MULTIPLY:
                self.take()
                v = v * self.power()
            elif val == "/":
                self.take()
                d = self.power()
                if d == 0:
                    raise ParseError("division by zero")
                v = v / d
            elif self.starts_factor():
                v = v * self.power()
            else:
                return v

    def power(self):
        if self.peek()[1] in ("+", "-"):  # a sign inside an exponent or after an operator
            return (-1 if self.take()[1] == "-" else 1) * self.power()
        v = self.primary()
        while self.peek()[1] == "^":
            self.take()
            e = self.power_exponent()
            if e.denominator != 1 or (v == 0 and e < 0):
                raise ParseError("bad power")
            v = v ** int(e)
        return v

    def power_exponent(self):
        if self.peek()[1] in ("+", "-"):
            return (-1 if self.take()[1] == "-" else 1) * self.power_exponent()
        return self.primary()

    def group(self, open_, close):
        self.take(open_)
        v = self.sum()
        self.take(close)
        return v

    def subscript(self):
        """_{...} or _x or [...]: part of a name, kept as text."""
        out = ""
        while self.peek()[1] in ("_", "["):
            opener = self.take()[1]
            if opener == "_" and self.peek()[1] != "{":
                out += "_" + self.take()[1]
                continue
            close = "}" if opener == "_" else "]"
            if opener == "_":
                self.take("{")
            depth, text = 1, ""
            while True:
                kind, val = self.take()
                if val in ("{", "["):
                    depth += 1
                elif val in ("}", "]"):
                    depth -= 1
                    if depth == 0 and val == close:
                        break
                text += val
            out += f"_{{{text}}}"
        return out

    def primary(self):
        kind, val = self.peek()
        if kind == "num":
            self.take()
            return Fraction(val)
        if val == "(":
            return self.group("(", ")")
        if val == "{":
            return self.group("{", "}")
        if val == "|":
            self.take()
            v = self.sum()
            self.take("|")
            return abs(v)
        if val == "\\frac":
            self.take()
            n = self.group("{", "}")
            d = self.group("{", "}")
            if d == 0:
                raise ParseError("division by zero")
            return n / d
        if val in FUNCTIONS and self.peek(1)[1] == "(":
            self.take()
            arg = self.group("(", ")")
            return draw(f"{val.lstrip(chr(92))}({arg})", self.point)
        if kind == "cmd" and val == "\\dot":
            self.take()
            kind2, val2 = self.take()
            return draw("dot" + val2 + self.subscript(), self.point)
        if kind in ("name", "cmd"):
            self.take()
            return draw(val.lstrip("\\") + self.subscript(), self.point)
        raise ParseError(f"unexpected {val}")


def values(text):
    """The values of an expression at two points, per side of its '=' signs; None if unparsable."""
    try:
        return tuple(tuple(Parser(part, p).parse() for p in (1, 2)) for part in split_top(text, "="))
    except (ParseError, ZeroDivisionError, OverflowError, RecursionError):
        return None


def split_top(text, sep):
    parts, depth, start = [], 0, 0
    for i, c in enumerate(text):
        if c in "({[":
            depth += 1
        elif c in ")}]":
            depth -= 1
        elif c == sep and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


# Spans that hold expressions, tried in this order; what is left of a line is compared as text.
LATEX_SPANS = [re.compile(p) for p in (
    r'data-tex="([^"]*)">([^<]*)<',  # HTML: the TeX source and the text shown before KaTeX runs
    r"\$\$(.+?)\$\$", r"\$(.+?)\$", r"\\\[(.+?)\\\]")]
ABS_SPAN = re.compile(r"\|([^\s|]+)\|")
GINAC_TOKEN = re.compile(r"[-+]?[A-Za-z0-9_{}\[\]().^*/+\-]+")


def unescape(line):
    line = line.replace("\\textasciicircum{}", "^")
    return re.sub(r"\\([*_|^])", r"\1", line)


def split_line(line, in_block):
    """(skeleton, spans): the line with each expression replaced by \\0, and the expressions."""
    if in_block:
        return "\0", [line]
    spans = []

    def keep(m):
        spans.extend(g for g in m.groups())
        return "\0" * len(m.groups())

    for pattern in LATEX_SPANS:
        line = pattern.sub(keep, line)
    line = unescape(line)
    line = ABS_SPAN.sub(lambda m: spans.append("|" + m.group(1) + "|") or "\0", line)

    def token(m):
        t = m.group(0)
        t = t.rstrip(".")
        while t.count(")") > t.count("(") and t.endswith(")"):
            t = t[:-1]
        rest = m.group(0)[len(t):]
        lead = ""
        while t.count("(") > t.count(")") and t.startswith("("):
            lead, t = lead + "(", t[1:]
        if ("*" in t or "^" in t) and re.search("[A-Za-z]", t):
            spans.append(t)
            return lead + "\0" + rest
        return m.group(0)

    line = GINAC_TOKEN.sub(token, line)
    return line, spans


def same_value(a, b, condition):
    """Equal values; for a condition (p = 0, or a span followed by = 0) also p against -p."""
    if a == b:
        return True
    va, vb = values(a), values(b)
    if va is None or vb is None or len(va) != len(vb):
        return False
    if va == vb:
        return True
    zero = (Fraction(0), Fraction(0))
    if len(va) == 2 and va[1] == vb[1] == zero:
        condition, va, vb = True, va[:1], vb[:1]
    return condition and len(va) == 1 and va[0] == tuple(-x for x in vb[0])


def equivalent(a, b):
    (sa, xa), (sb, xb) = a, b
    if sa != sb or len(xa) != len(xb):
        return False
    # A span followed by " = 0", or the "polynomial" of an exceptional set in JSON, is a condition:
    # its sign does not matter.
    chunks = sa.split("\0")
    for k, (p, q) in enumerate(zip(xa, xb)):
        condition = re.match(r"\s*=\s*0\b", chunks[k + 1]) or chunks[k].endswith('"polynomial": "')
        if not same_value(p, q, bool(condition)):
            return False
    return True


def blocks(lines):
    """For each line, whether it lies inside a Markdown $$ ... $$ display block."""
    inside, out = False, []
    for line in lines:
        if line.strip() == "$$":
            inside = not inside
            out.append(False)
        else:
            out.append(inside)
    return out


def main(old_path, new_path):
    old = open(old_path, encoding="utf-8", errors="replace").read().splitlines()
    new = open(new_path, encoding="utf-8", errors="replace").read().splitlines()
    bo, bn = blocks(old), blocks(new)
    sm = difflib.SequenceMatcher(None, old, new, autojunk=False)
    left, right = [], []
    for tag, i1, i2, j1, j2 in sm.get_opcodes():
        if tag != "equal":
            left.extend(range(i1, i2))
            right.extend(range(j1, j2))
    if len(left) != len(right):
        return 1
    split_new = {j: split_line(new[j], bn[j]) for j in right}
    unused = list(right)
    for i in left:
        a = split_line(old[i], bo[i])
        match = next((j for j in unused if equivalent(a, split_new[j])), None)
        if match is None:
            return 1
        unused.remove(match)
    print(len(left))
    return 0


if __name__ == "__main__":
    sys.setrecursionlimit(10000)
    sys.exit(main(sys.argv[1], sys.argv[2]))
