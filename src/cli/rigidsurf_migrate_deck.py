"""A LIGGGHTS deck read and followed as LIGGGHTS 3.8 runs it, or a LAMMPS deck as LAMMPS
29Sep2021 runs it (part of rigidsurf-migrate).

Reading (Input::file, Input::parse): a line whose last printable character is & goes on
with the next line, which takes the place of the & and what follows it; # starts a
comment outside quotes; words are split at whitespace, a quoted word ("..." or '...') is
one word without its quotes. Substitution (Input::substitute), outside quotes: ${name}
and $x (one letter) become the variable's value (an equal-style one written with
%.15g), $(formula) the formula's value (%.20g).

Following (Input::execute_command): the tool runs the deck's own commands in LIGGGHTS's
order: `variable` (index, loop, string, equal, atom, world, universe, uloop, delete; a
value read from a file or the environment is the run's), `next` (the jump after an
exhausted variable is skipped), `label`, `jump SELF|FILE [label]`, `include`, `if`
(its commands run through the same path), `run` (the step count), `timestep`,
`reset_timestep`, `quit`. Every other command is recorded, in the order it runs, with its
words as substituted (Exec). A loop that runs the same commands twice in a row, none of
which makes, moves or removes a fix, dump or compute, is not run pass by pass: its
variables go on to their last pass, which runs, and the steps of the passes between are
counted. Where a value depends on the run (a thermo value, a compute,
a fix), the words hold it as unknown; an `if` whose condition depends on the run is
recorded in blind, its commands not run; where such an `if` changes the deck's flow
(jump, label, include, next) the tool stops following (stopped) and the rest is what the
caller may only read. What LIGGGHTS would stop at stops the tool: DeckError, with the
file and line.

LAMMPS (Deck(..., engine="lammps")), whose input language LIGGGHTS's is a fork of, reads
and follows the same way, and also: triple quotes (three double quotes around one word,
a # or $ inside kept), `$(formula:%.6g)` (the immediate value in that format), the
variable styles format, internal, vector, timer and python, and its formulas' rules
(rigidsurf_migrate_expr.py, lmp).
"""
import os

import re

import rigidsurf_migrate_expr as expr

UNKNOWN = "\x00"       # marks a word whose value depends on the run
MAX_COMMANDS = 200000  # the longest run of commands the tool follows
FLOW = ("jump", "label", "include", "next", "clear")
# commands that may make, move, write or remove a wall: a loop that runs one is followed
# pass by pass
WALLISH = ("fix", "unfix", "dump", "undump", "compute", "uncompute", "fix_modify")
FORMAT = re.compile(r"%[0-9 ]*\.[0-9]+[efgEFG]")   # LAMMPS's numeric formats

class DeckError(Exception):
    """LIGGGHTS (or the tool) stops here: where (a Command or None) and why."""

    def __init__(self, where, message):
        Exception.__init__(self, message)
        self.where = where


class Source:
    """One file of the deck: its name as the deck names it, its path, its commands (lmp:
    read as LAMMPS reads it)."""

    def __init__(self, name, path, text, lmp=False):
        self.name, self.path, self.lmp = name, path, lmp
        self.commands = read_commands(self, text)


class Command:
    """One command of a file: its physical lines (newlines kept), the number of its first
    line, the line as LIGGGHTS joins it, that line without its comment, and the
    comment."""

    def __init__(self, source, index, lineno, raw):
        self.source, self.index, self.lineno, self.raw = source, index, lineno, raw
        text = ""
        for k, phys in enumerate(raw):
            s = phys.rstrip("\n").rstrip()
            if k < len(raw) - 1:       # ends in &: the next line goes where the & was
                s = s[:-1]
            text += s
        self.text = text
        lmp = getattr(source, "lmp", False)
        cut = comment_start(text, lmp)
        self.body = text if cut is None else text[:cut]
        self.comment = "" if cut is None else text[cut:].rstrip()
        self.raw_words = split_words(self.body, self, strict=False, triple=lmp)

    def where(self):
        return "LINE %d%s" % (self.lineno, "" if self.source.name is None
                              else " of %s" % self.source.name)


def comment_start(text, triple=False):
    quote, i = None, 0
    while i < len(text):
        ch = text[i]
        if quote:
            if quote == '"""' and text.startswith(quote, i):
                quote = None
                i += 2
            elif ch == quote:
                quote = None
        elif triple and text.startswith('"""', i):
            quote = '"""'
            i += 2
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            return i
        i += 1
    return None


def read_commands(source, text):
    lines = text.splitlines(keepends=True)
    out, i = [], 0
    while i < len(lines):
        j = i
        while j < len(lines) - 1 and lines[j].rstrip().endswith("&"):
            j += 1
        out.append(Command(source, len(out), i + 1, lines[i:j + 1]))
        i = j + 1
    return out


def split_words(text, cmd, strict=True, triple=False):
    """Input::nextword: whitespace-separated words, a quoted one without its quotes
    (triple: LAMMPS's triple quotes too)."""
    words, i, n = [], 0, len(text)
    while True:
        while i < n and text[i] in " \t\n\v\f\r":
            i += 1
        if i >= n:
            return words
        if text[i] in "\"'":
            q = '"""' if triple and text.startswith('"""', i) else text[i]
            k = text.find(q, i + len(q))
            if k < 0:
                if strict:
                    raise DeckError(cmd, "Unbalanced quotes in input line")
                k = n
            end = k + len(q)
            if strict and end < n and not text[end].isspace():
                raise DeckError(cmd, "Input line quote not followed by whitespace")
            words.append(text[i + len(q):k])
            i = end
        else:
            k = i
            while k < n and text[k] not in " \t\n\v\f\r":
                k += 1
            words.append(text[i:k])
            i = k


def known(word):
    return UNKNOWN not in word


class Var:
    def __init__(self, style, values=None, text=None, pad=0):
        self.style, self.values, self.text, self.pad, self.which = style, values, text, pad, 0


class Exec:
    """One command as it ran: its Command (or, run by an `if`, the if's), its words as
    substituted, the `if` that ran it (or None), and the step and time step then; a
    `run` also its steps (nsteps, None where the tool cannot count them)."""

    def __init__(self, cmd, words, via, step, dt):
        self.cmd, self.words, self.via, self.step, self.dt = cmd, words, via, step, dt
        self.nsteps = None
        raw = cmd.raw_words if via is None else None
        # the words as written stand for those substituted where they are one each
        self.raw = raw if raw is not None and len(raw) == len(words) and all(
            r == x or "$" in r for r, x in zip(raw, words)) else None

    def rawword(self, i, word):
        """Word i as written where it can stand for word (at this command's place), else
        word."""
        return self.raw[i] if self.raw is not None else word


class Deck:
    """The deck at path followed (Deck.follow): trace (the Exec of each command run, in
    order), sources (every file read, the deck first), blind and stopped (above)."""

    def __init__(self, path, cli_vars=(), engine="liggghts"):
        self.dir = os.path.dirname(os.path.abspath(path))
        self.lmp = engine == "lammps"
        self.sources = {}
        self.main = self.source(None, path, None)
        self.vars = {}
        for name, values in cli_vars:
            self.vars[name] = Var("index", list(values))
        self.trace, self.blind, self.stopped = [], [], None
        self.ran, self.loops = [], {}   # every command run; the passes of each jump
        self.step, self.dt, self.time = 0, None, 0.0
        self.unknown = {}       # why a word is unknown: reason by marker
        self.evaluating = set()
        # observer(exec): called as each command is recorded, the deck's variables, step
        # and time then as they are where it runs
        self.observer = None

    # -- files --------------------------------------------------------------------
    def resolve(self, name):
        """A file the deck names, as LIGGGHTS opens it from the deck's folder."""
        for base in (self.dir, os.getcwd()):
            p = os.path.join(base, name)
            if os.path.isfile(p):
                return p
        return None

    def source(self, name, path, cmd):
        if path in self.sources:
            return self.sources[path]
        try:
            with open(path, newline="") as f:
                text = f.read()
        except (OSError, UnicodeDecodeError) as e:
            raise DeckError(cmd, "Cannot open input script %s (%s)" % (name or path, e))
        src = Source(name, path, text, self.lmp)
        self.sources[path] = src
        return src

    # -- values -------------------------------------------------------------------
    def mark(self, reason):
        key = UNKNOWN + str(len(self.unknown)) + UNKNOWN
        self.unknown[key] = reason
        return key

    def why(self, word):
        """Why a word's value is unknown (the first reason it holds)."""
        for key, reason in self.unknown.items():
            if key in word:
                return reason
        return None

    def retrieve(self, name, cmd):
        v = self.vars.get(name)
        if v is None or v.which >= len(v.values or [None]):
            raise DeckError(cmd, "Substitution for illegal variable %s" % name)
        if v.style in ("index", "world", "universe", "string"):
            return v.values[v.which]
        if v.style in ("loop", "uloop"):
            return ("%0*d" % (v.pad, v.which + 1)) if v.pad else "%d" % (v.which + 1)
        if v.style == "equal":
            return expr.g15(self.equal(name, cmd))
        if v.style == "format":
            return self.formatted(v, cmd)
        if v.style == "internal":
            return expr.g15(v.values[0])
        if v.style == "run":
            raise expr.Unknown(v.text)
        raise DeckError(cmd, "Substitution for illegal variable %s" % name)

    def formatted(self, v, cmd):
        """A LAMMPS format-style variable: its equal-style variable's value, formatted."""
        src = self.vars.get(v.values[0])
        if src is None or src.style not in ("equal", "internal", "format"):
            raise DeckError(cmd, "Variable %s for format is invalid style" % v.values[0])
        val = src.values[0] if src.style == "internal" else \
            expr.atof(self.retrieve(v.values[0], cmd)) if src.style == "format" else \
            self.equal(v.values[0], cmd)
        return v.values[1] % val

    def equal(self, name, cmd):
        if name in self.evaluating:
            raise DeckError(cmd, "Variable has circular dependency")
        self.evaluating.add(name)
        try:
            return self.formula(self.vars[name].text, cmd)
        finally:
            self.evaluating.discard(name)

    def formula(self, text, cmd):
        deck = self

        class Env:
            def variable(self, name):
                v = deck.vars.get(name)
                if v is None:
                    raise expr.FormulaError("Invalid variable name in variable formula")
                if v.style == "atom":
                    raise expr.FormulaError("Atom-style variable in equal-style variable "
                                            "formula")
                if v.style == "internal":
                    return v.values[0]
                return expr.atof(deck.retrieve(name, cmd))

            def thermo(self, word):
                if word == "step" and deck.step is not None:
                    return float(deck.step)
                if word == "dt" and deck.dt is not None:
                    return deck.dt
                if word == "time" and deck.time is not None:
                    return deck.time
                raise expr.Unknown("the thermo keyword %s (the run's)" % word)
        try:
            return expr.evaluate(text, Env(), self.lmp)
        except expr.FormulaError as e:
            raise DeckError(cmd, "%s: %s" % (text, e))

    def substitute(self, text, cmd):
        """Input::substitute: $ outside quotes; an unknown value becomes a marker."""
        out, i, dq, sq, tq = "", 0, False, False, False
        while i < len(text):
            ch = text[i]
            if self.lmp and not dq and not sq and text.startswith('"""', i):
                tq = not tq
                out += '"""'
                i += 3
                continue
            if ch == "$" and not dq and not sq and not tq:
                nxt = text[i + 1:i + 2]
                if nxt == "{":
                    k = text.find("}", i + 2)
                    if k < 0:
                        raise DeckError(cmd, "Invalid variable name")
                    name, end = text[i + 2:k], k + 1
                elif nxt == "(":
                    try:
                        k = expr.matching_paren(text, i + 1)
                    except expr.FormulaError:
                        raise DeckError(cmd, "Invalid immediate variable")
                    name, end = None, k + 1
                else:
                    name, end = nxt, i + 2
                try:
                    if name is None:
                        inner, fmt = text[i + 2:end - 1], "%.20g"
                        k = inner.rfind(":")
                        if self.lmp and k >= 0 and inner[k + 1:k + 2] == "%":
                            inner, fmt = inner[:k], inner[k + 1:]
                            if not FORMAT.fullmatch(fmt):
                                raise DeckError(cmd, "Incorrect conversion in format "
                                                "string")
                        out += fmt % self.formula(inner, cmd)
                    else:
                        out += self.retrieve(name, cmd)
                except expr.Unknown as e:
                    out += self.mark("%s in %s" % (str(e), text[i:end]))
                i = end
                continue
            if self.lmp:    # LAMMPS: a quote ends at its own kind
                if ch == '"' and not sq and not tq:
                    dq = not dq
                elif ch == "'" and not dq and not tq:
                    sq = not sq
            elif ch == '"':
                dq = not dq
            elif ch == "'":
                sq = not sq
            out += ch
            i += 1
        return out

    # -- following ------------------------------------------------------------------
    def follow(self):
        """Runs the deck's commands in LIGGGHTS's order; returns self."""
        stack = self.stack = [[self.main, 0]]
        label, count = None, 0
        self.jump_skip = False   # an exhausted `next` skips the next jump (Input::jump)
        while stack:
            src, pos = stack[-1]
            if pos >= len(src.commands):
                if label is not None:
                    raise DeckError(None, "Label wasn't found in input script: %s" % label)
                stack.pop()
                continue
            cmd = src.commands[pos]
            stack[-1][1] = pos + 1
            count += 1
            if count > MAX_COMMANDS:
                raise DeckError(cmd, "the deck's loops run more than %d commands: the tool "
                                "does not follow them further" % MAX_COMMANDS)
            if label is not None:
                w = cmd.raw_words
                if w[:1] == ["label"] and w[1:2] == [label]:
                    label = None
                continue
            words = split_words(self.substitute(cmd.body, cmd), cmd, triple=self.lmp)
            if not words:
                continue
            self.ran.append((cmd, words))
            res = self.execute(cmd, words, None, stack)
            if res == "quit":
                return self
            if isinstance(res, tuple) and res[0] == "label":
                label = res[1]
            elif res == "stop":
                return self
        return self

    def execute(self, cmd, words, via, stack):
        name, args = words[0], words[1:]
        if name == "variable":
            self.variable(cmd, args)
        elif name == "next":
            self.jump_skip |= self.next_vars(cmd, args)
        elif name == "label":
            pass
        elif name == "jump":
            if self.jump_skip:
                self.jump_skip = False
                return None
            return self.jump(cmd, args, via, stack)
        elif name == "include":
            if via is not None:
                raise DeckError(via, "Cannot use include command within an if command")
            if len(args) != 1 or not known(args[0]):
                raise DeckError(cmd, "Illegal include command")
            path = self.resolve(args[0])
            if path is None:
                raise DeckError(cmd, "Cannot open input script %s" % args[0])
            stack.append([self.source(args[0], path, cmd), 0])
            cmd.source.includes = getattr(cmd.source, "includes", {})
            cmd.source.includes[cmd.index] = path
        elif name == "if":
            return self.ifthen(cmd, args, via, stack)
        elif name == "quit":
            return "quit"
        else:
            self.trace.append(Exec(cmd, words, via, self.step, self.dt))
            if self.observer is not None:
                self.observer(self.trace[-1])
            self.track(cmd, words)
        return None

    def track(self, cmd, words):
        """The step, time step and time that run, timestep and reset_timestep change."""
        name = words[0]
        if name == "timestep" and len(words) > 1:
            dt = expr.atof(words[1]) if known(words[1]) else None
            self.dt = dt
        elif name == "read_restart":
            self.step = self.time = None   # the restart file's
        elif name == "reset_timestep" and len(words) > 1:
            self.step = int(expr.atof(words[1])) if known(words[1]) else None
            self.time = None
        elif name == "run" and len(words) > 1:
            n = int(expr.atof(words[1])) if known(words[1]) else None
            upto = "upto" in words[2:]
            if n is None or self.step is None and upto:
                nsteps = None
            else:
                nsteps = n - self.step if upto else n
            self.trace[-1].nsteps = nsteps
            self.step = None if nsteps is None or self.step is None else self.step + nsteps
            if self.time is not None and nsteps is not None and self.dt is not None:
                self.time += nsteps * self.dt
            else:
                self.time = None

    def variable(self, cmd, a):
        if len(a) < 2:
            raise DeckError(cmd, "Illegal variable command")
        name, style = a[0], a[1]
        old = self.vars.get(name)
        if style == "delete":
            self.vars.pop(name, None)
            return
        if not name.replace("_", "a").isalnum():
            raise DeckError(cmd, "Variable name must be alphanumeric or underscore "
                            "characters")
        if style in ("index", "loop", "world", "universe", "uloop", "file", "atomfile"):
            if old is not None:
                return           # LIGGGHTS keeps the first definition
            if style in ("index", "world", "universe"):
                if len(a) < 3:
                    raise DeckError(cmd, "Illegal variable command")
                self.vars[name] = Var(style, a[2:])
            elif style in ("loop", "uloop"):
                pad = a[-1] == "pad"
                nums = a[2:-1] if pad else a[2:]
                try:
                    lims = [int(x) for x in nums]
                except ValueError:
                    raise DeckError(cmd, "Expected integer parameter in variable definition")
                if len(lims) not in (1, 2) or style == "uloop" and len(lims) != 1:
                    raise DeckError(cmd, "Illegal variable command")
                first, last = (1, lims[0]) if len(lims) == 1 else lims
                v = Var("loop", [None] * last, pad=len(str(last)) if pad else 0)
                v.which = first - 1
                self.vars[name] = v
            else:
                self.vars[name] = Var("run", [None], "the variable %s read from a file "
                                      "(the run's)" % name)
            return
        if style in ("string", "getenv", "equal", "atom"):
            if len(a) != 3:
                raise DeckError(cmd, "Illegal variable command")
            want = "run" if style == "getenv" else style
            if old is not None and old.style != want and not (style == "getenv" and
                                                                old.style == "run"):
                raise DeckError(cmd, "Cannot redefine variable as a different style")
            if style == "string":
                self.vars[name] = Var("string", [a[2]])
            elif style == "getenv":
                self.vars[name] = Var("run", [None], "the environment's %s (the run's)"
                                      % a[2])
            else:
                self.vars[name] = Var(style, [None], a[2])
            return
        if self.lmp and style in ("format", "internal", "vector", "python", "timer"):
            return self.lammps_variable(cmd, name, style, a, old)
        raise DeckError(cmd, "Illegal variable command")

    def lammps_variable(self, cmd, name, style, a, old):
        """LAMMPS's variable styles that LIGGGHTS has not (Variable::set)."""
        if style == "timer":
            self.vars[name] = Var("run", [None], "the timer variable %s (the run's)" % name)
            return
        if len(a) != (4 if style == "format" else 3):
            raise DeckError(cmd, "Illegal variable command")
        if style == "format":
            if old is not None:
                return           # LAMMPS keeps the first definition
            if not FORMAT.fullmatch(a[3]):
                raise DeckError(cmd, "Incorrect conversion in format string")
            self.vars[name] = Var("format", [a[2], a[3]])
            return
        if old is not None and old.style != style and not (
                old.style == "run" and style in ("vector", "python")):
            raise DeckError(cmd, "Cannot redefine variable as a different style")
        if style == "internal":
            v = expr.atof(a[2]) if known(a[2]) else None
            self.vars[name] = Var("internal", [v]) if v is not None else \
                Var("run", [None], "the internal variable %s (the run's)" % name)
        else:
            self.vars[name] = Var("run", [None], "the %s variable %s (the run's)" % (
                style, name))

    def next_vars(self, cmd, names):
        if not names:
            raise DeckError(cmd, "Illegal next command")
        done = False
        for n in names:
            v = self.vars.get(n)
            if v is None:
                raise DeckError(cmd, "Invalid variable in next command")
            if v.style not in ("index", "loop", "universe", "uloop"):
                raise DeckError(cmd, "Invalid variable style with next command")
            v.which += 1
            if v.which >= len(v.values):
                done = True
                del self.vars[n]
        return done

    def jump(self, cmd, args, via, stack):
        if not 1 <= len(args) <= 2:
            raise DeckError(cmd, "Illegal jump command")
        if not all(known(x) for x in args):
            return self.stop(via or cmd, "jump %s: %s" % (" ".join(args), self.why(
                " ".join(args))), stack, [None])
        if via is None:
            self.loop_ahead(cmd)
        if args[0] == "SELF":
            stack[-1][1] = 0
        else:
            path = self.resolve(args[0])
            if path is None:
                raise DeckError(cmd, "Cannot open input script %s" % args[0])
            stack[-1] = [self.source(args[0], path, cmd), 0]
            (via or cmd).source.jumps = getattr((via or cmd).source, "jumps", set())
            (via or cmd).source.jumps.add(path)
        return ("label", args[1]) if len(args) == 2 else None

    def loop_ahead(self, cmd):
        """At a jump that closes a loop: when its last two passes ran the same commands,
        none of WALLISH, the loop variables (those of its `next`) go on to their last
        pass, and the step and time to where the passes between would take them; a
        `run` of those steps stands for them in the trace. Variables the pass sets from
        substituted values are the run's from here."""
        here = len(self.ran)
        prev = self.loops.get(cmd)
        self.loops[cmd] = (here, None, self.step, self.time)
        if prev is None:
            return
        start, sig_prev, step_prev, time_prev = prev
        body = self.ran[start:here]
        sig = tuple(c for c, _ in body)
        self.loops[cmd] = (here, sig, self.step, self.time)
        if sig != sig_prev or any(w[0] in WALLISH for _, w in body):
            return
        nexts = [n for _, w in body if w[0] == "next" for n in w[1:]]
        if not nexts or any(n not in self.vars for n in nexts):
            return
        ahead = min(len(self.vars[n].values) - self.vars[n].which for n in nexts) - 1
        if ahead <= 0:
            return
        for n in nexts:
            self.vars[n].which += ahead
        per = None if self.step is None or step_prev is None else self.step - step_prev
        ex = Exec(cmd, ["run", str(per * ahead) if per is not None else UNKNOWN], None,
                  self.step, self.dt)
        ex.nsteps = None if per is None else per * ahead
        self.trace.append(ex)
        self.step = None if per is None else self.step + per * ahead
        self.time = None if self.time is None or time_prev is None else \
            self.time + (self.time - time_prev) * ahead
        for c, w in body:
            if w[0] == "variable" and len(w) > 2 and "$" in c.body and w[1] not in nexts:
                self.vars[w[1]] = Var("run", [None], "%s, set by the loop of %s" % (
                    w[1], cmd.where()))

    def ifthen(self, cmd, args, via, stack):
        if len(args) < 3 or args[1] != "then":
            raise DeckError(cmd, "Illegal if command")
        branches, cond, k = [], args[0], 2
        while True:
            j = k
            while j < len(args) and args[j] not in ("elif", "else"):
                j += 1
            branches.append((cond, args[k:j]))
            if j >= len(args):
                break
            if args[j] == "elif":
                if j + 2 > len(args):
                    raise DeckError(cmd, "Illegal if command")
                cond, k = args[j + 1], j + 2
            else:
                cond, k = None, j + 1
        for cond, cmds in branches:
            if not cmds or any(not c for c in cmds):
                raise DeckError(cmd, "Illegal if command")
            if cond is not None:
                text = self.substitute(cond, cmd)
                try:
                    if text.startswith("property_"):
                        raise expr.Unknown("%s (whether the run holds that property)"
                                           % text)
                    if not known(text):
                        raise expr.Unknown(self.why(text))
                    test = expr.evaluate_boolean(text, self.lmp)
                except expr.FormulaError as e:
                    raise DeckError(cmd, "%s: %s" % (text, e))
                except expr.Unknown as e:
                    return self.blind_if(cmd, branches, str(e))
                if test == 0.0:
                    continue
            for c in cmds:
                words = split_words(self.substitute(c, cmd), cmd, triple=self.lmp)
                if not words:
                    continue
                res = self.execute(cmd, words, cmd, stack)
                if res is not None:
                    return res
            return None
        return None

    def blind_if(self, cmd, branches, reason):
        """An `if` whose condition depends on the run: its commands do not run; the
        variables they set are unknown from here, and a `run` in them makes the step
        unknown. One that changes the deck's flow stops the following."""
        self.blind.append((cmd, reason, branches))
        for _, cmds in branches:
            for c in cmds:
                w = split_words(c, cmd, strict=False)
                if w[:1] and w[0] in FLOW:
                    jumps = [split_words(x, cmd, strict=False)[1:] for _, xs in branches
                             for x in xs if split_words(x, cmd, strict=False)[:1] == ["jump"]]
                    return self.stop(cmd, reason, targets=jumps)
                if w[:1] == ["variable"] and len(w) > 1:
                    self.vars[w[1]] = Var("run", [None], "%s, set by the if of %s" % (
                        reason, cmd.where()))
                if w[:1] == ["run"]:
                    self.step = self.time = None
        return None

    def stop(self, cmd, reason, stack=None, targets=()):
        """Stops following at cmd: LIGGGHTS may go on after each open file's place
        (stack), and at each jump's target (targets: the jumps' words; None for a target
        the tool does not know)."""
        self.stopped = (cmd, reason, [(s, p) for s, p in (stack or self.stack)], targets)
        return "stop"
