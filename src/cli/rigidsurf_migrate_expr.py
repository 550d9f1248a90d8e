"""LIGGGHTS's and LAMMPS's formulas as LIGGGHTS 3.8 and LAMMPS 29Sep2021 evaluate them
(part of rigidsurf-migrate).

An equal-style formula (Variable::evaluate): numbers, PI, thermo keywords, v_name, c_ID
and f_ID with brackets, the math functions, group and special functions, parentheses
and the operators, evaluated with LIGGGHTS's operator stack: unary minus and ! bind
tightest (so -2^2 is 4), then ^, then * / %, + -, < <= > >=, == !=, &&, ||; operators of
one level group from the left (2^3^2 is 64). x^0, x/0 and x%0 are errors, as LIGGGHTS
makes them.

An `if` condition (Variable::evaluate_boolean): numbers (a leading - belongs to the
number), parentheses and the comparison and logical operators only.

LAMMPS (lmp = True) is LIGGGHTS's parent with three differences here: x^0 is 1 (0 to a
negative power an error), `|^` is exclusive or (at the level of ||), and an `if`
condition may compare words (`yes == yes`) with == and !=.

What the deck cannot know before it runs (a thermo value, a compute, a fix, an atom)
raises Unknown; what LIGGGHTS would stop at raises FormulaError with its message.
"""
import math
import re

# LIGGGHTS's precedence levels (Variable::Variable)
PREC = {"||": 1, "|^": 1, "&&": 2, "==": 3, "!=": 3, "<": 4, "<=": 4, ">": 4, ">=": 4, "+": 5,
        "-": 5, "*": 6, "/": 6, "%": 6, "^": 7, "neg": 8, "!": 8}
MATH1 = {"sqrt": None, "exp": math.exp, "ln": None, "log": None, "abs": abs,
         "sin": math.sin, "cos": math.cos, "tan": math.tan, "asin": None, "acos": None,
         "atan": math.atan, "ceil": math.ceil, "floor": math.floor, "round": None}
# functions whose value only the run knows (random numbers, the run's own steps, atoms)
RUN_FUNCTIONS = ("random", "normal", "ramp", "stagger", "logfreq", "stride", "vdisplace",
                 "swiggle", "cwiggle", "count", "mass", "charge", "xcm", "vcm", "fcm",
                 "bound", "gyration", "ke", "angmom", "torque", "inertia", "omega", "sum",
                 "min", "max", "ave", "trap", "gmask", "rmask", "grmask", "next",
                 "logfreq2", "logfreq3", "stride2", "slope", "is_active", "is_available",
                 "is_defined", "is_file")
NUMBER = re.compile(r"[0-9.]*([eE][+-]?[0-9]*)?")
ATOF = re.compile(r"\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


class Unknown(Exception):
    """The value depends on the run; the message names what."""


class FormulaError(Exception):
    """LIGGGHTS stops here; the message is LIGGGHTS's."""


def atof(text):
    """C's atof: the longest number at the start, else 0."""
    m = ATOF.match(text)
    return float(m.group(0)) if m else 0.0


def g15(v):
    """A number as LIGGGHTS writes an equal-style variable's value (%.15g)."""
    return "%.15g" % v


def matching_paren(text, i):
    """The index of the parenthesis closing the one at text[i]."""
    depth = 0
    for k in range(i, len(text)):
        if text[k] == "(":
            depth += 1
        elif text[k] == ")":
            depth -= 1
            if depth == 0:
                return k
    raise FormulaError("Unbalanced parentheses in variable formula")


def split_args(text):
    """The arguments of a function, split at the commas outside parentheses."""
    out, depth, cur = [], 0, ""
    for ch in text:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    return out + [cur]


def apply(op, stack, lmp=False, boolean=False):
    b = stack.pop()
    if op == "neg":
        stack.append(-b)
        return
    if op == "!":
        if isinstance(b, str):
            raise FormulaError("Invalid Boolean syntax in if command")
        stack.append(1.0 if b == 0.0 else 0.0)
        return
    a = stack.pop()
    if isinstance(a, str) or isinstance(b, str):
        # LAMMPS's conditions compare words with == and != only
        if op not in ("==", "!=") or not (isinstance(a, str) and isinstance(b, str)):
            raise FormulaError("Invalid Boolean syntax in if command")
        stack.append(float((a == b) == (op == "==")))
        return
    if op == "/" and b == 0.0:
        raise FormulaError("Divide by 0 in variable formula")
    if op == "%" and b == 0.0:
        raise FormulaError("Modulo 0 in variable formula")
    if op == "^" and b == 0.0 and lmp:
        stack.append(1.0)
        return
    if op == "^" and a == 0.0 and b < 0.0 and lmp:
        raise FormulaError("Invalid power expression in variable formula")
    if op == "^" and b == 0.0:
        raise FormulaError("Power by 0 in variable formula")
    if op == "^":
        try:
            v = math.pow(a, b)
        except (ValueError, OverflowError):
            v = math.nan if a < 0 else math.inf
        stack.append(v)
        return
    stack.append({"+": lambda: a + b, "-": lambda: a - b, "*": lambda: a * b,
                  "/": lambda: a / b, "%": lambda: math.fmod(a, b),
                  "==": lambda: float(a == b), "!=": lambda: float(a != b),
                  "<": lambda: float(a < b), "<=": lambda: float(a <= b),
                  ">": lambda: float(a > b), ">=": lambda: float(a >= b),
                  "&&": lambda: float(a != 0.0 and b != 0.0),
                  "||": lambda: float(a != 0.0 or b != 0.0),
                  "|^": lambda: float((a != 0.0) != (b != 0.0))}[op]())


def operator_at(text, i, boolean, lmp=False):
    """The operator at text[i] and its length, as LIGGGHTS (LAMMPS) reads it."""
    two = text[i:i + 2]
    if two in ("==", "!=", "<=", ">=", "&&", "||") or lmp and two == "|^":
        return two, 2
    ch = text[i]
    if ch in "=&|":
        raise FormulaError("Invalid %ssyntax in %s" % (
            "Boolean " if boolean else "", "if command" if boolean else "variable formula"))
    if boolean and ch not in "<>!":
        return None, 0
    return ch, 1


def run_stack(text, boolean, operand, lmp=False):
    """LIGGGHTS's (LAMMPS's) operator-stack evaluation of text; operand(text, i) reads an
    operand at i and returns (value, next index)."""
    what = "if command" if boolean else "variable formula"
    bad = "Invalid %ssyntax in %s" % ("Boolean " if boolean else "", what)
    args, ops, i, expect_arg = [], [], 0, True
    while True:
        while i < len(text) and text[i].isspace():
            i += 1
        if i < len(text) and text[i] not in "+-*/^<>=!&|%" or \
                (boolean and i < len(text) and text[i] == "-"):
            if not expect_arg:
                raise FormulaError(bad)
            v, i = operand(text, i)
            args.append(v)
            expect_arg = False
            continue
        if i >= len(text):
            op, n = "end", 0
        else:
            op, n = operator_at(text, i, boolean, lmp)
            if op is None:
                raise FormulaError(bad)
        i += n
        if expect_arg and op == "-" and not boolean:
            ops.append("neg")
            continue
        if expect_arg and op == "!":
            ops.append("!")
            continue
        if expect_arg:
            raise FormulaError(bad)
        expect_arg = True
        prec = 0 if op == "end" else PREC[op]
        while ops and PREC[ops[-1]] >= prec:
            apply(ops.pop(), args, lmp)
        if op == "end":
            break
        ops.append(op)
    if ops or len(args) != 1:
        raise FormulaError(bad)
    return args[0]


def evaluate_boolean(text, lmp=False):
    """The value of an `if` condition (after substitution)."""
    def operand(t, i):
        if t[i] == "(":
            j = matching_paren(t, i)
            return evaluate_boolean(t[i + 1:j], lmp), j + 1
        if lmp and t[i].isalpha():
            j = i + 1
            while j < len(t) and (t[j].isalnum() or t[j] in "_/"):
                j += 1
            return t[i:j], j
        if not (t[i].isdigit() or t[i] in ".-"):
            raise FormulaError("Invalid Boolean syntax in if command")
        j = i + 1
        while j < len(t) and (t[j].isdigit() or t[j] == "."):
            j += 1
        if j < len(t) and t[j] in "eE":
            j += 1
            if j < len(t) and t[j] in "+-":
                j += 1
            while j < len(t) and t[j].isdigit():
                j += 1
        return atof(t[i:j]), j
    v = run_stack(text, True, operand, lmp)
    if isinstance(v, str):
        raise FormulaError("Invalid Boolean syntax in if command")
    return v


def evaluate(text, env, lmp=False):
    """The value of an equal-style formula. env answers env.variable(name) (the value of
    v_name, as LIGGGHTS retrieves it) and env.thermo(word) (a thermo keyword); both raise
    Unknown where the deck cannot know the value."""
    def operand(t, i):
        ch = t[i]
        if ch == "(":
            j = matching_paren(t, i)
            return evaluate(t[i + 1:j], env, lmp), j + 1
        if ch.isdigit() or ch == ".":
            m = NUMBER.match(t, i)
            return atof(m.group(0)), m.end()
        if not ch.isalpha():
            raise FormulaError("Invalid syntax in variable formula")
        j = i
        while j < len(t) and (t[j].isalnum() or t[j] == "_"):
            j += 1
        word = t[i:j]
        if j < len(t) and t[j] == "(":
            k = matching_paren(t, j)
            return function(word, t[j + 1:k], env, lmp), k + 1
        brackets = ""
        while j < len(t) and t[j] == "[":
            k = t.find("]", j)
            if k < 0:
                raise FormulaError("Invalid syntax in variable formula")
            brackets += t[j:k + 1]
            j = k + 1
        return reference(word, brackets, env), j
    return run_stack(text, False, operand, lmp)


def reference(word, brackets, env):
    if word.startswith(("c_", "f_")):
        raise Unknown("%s%s (the run's)" % (word, brackets))
    if word.startswith("v_"):
        if brackets:
            raise Unknown("%s%s (an atom's)" % (word, brackets))
        return env.variable(word[2:])
    if brackets:
        raise Unknown("%s%s (an atom's)" % (word, brackets))
    if word == "PI":
        return math.pi
    return env.thermo(word)


def function(word, inner, env, lmp=False):
    if word in RUN_FUNCTIONS:
        raise Unknown("%s() (the run's)" % word)
    args = split_args(inner)
    if word == "atan2":
        if len(args) != 2:
            raise FormulaError("Invalid math function in variable formula")
        return math.atan2(evaluate(args[0], env, lmp), evaluate(args[1], env, lmp))
    if word not in MATH1:
        raise FormulaError("Invalid math function in variable formula")
    if len(args) != 1:
        raise FormulaError("Invalid math function in variable formula")
    v = evaluate(args[0], env, lmp)
    if word == "sqrt":
        if v < 0.0:
            raise FormulaError("Sqrt of negative value in variable formula")
        return math.sqrt(v)
    if word in ("ln", "log"):
        if v <= 0.0:
            raise FormulaError("Log of zero/negative value in variable formula")
        return math.log(v) if word == "ln" else math.log10(v)
    if word in ("asin", "acos"):
        if v < -1.0 or v > 1.0:
            raise FormulaError("Arc%s of invalid value in variable formula"
                               % ("sin" if word == "asin" else "cos"))
        return math.asin(v) if word == "asin" else math.acos(v)
    if word == "round":  # LIGGGHTS's MYROUND: halves away from the floor
        return float(math.ceil(v) if v - math.floor(v) >= 0.5 else math.floor(v))
    try:
        return float(MATH1[word](v))
    except OverflowError:
        return math.inf
