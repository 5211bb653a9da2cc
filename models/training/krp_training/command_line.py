"""A command written down for a report or a log: one line that a shell reads back as the same
arguments, so that a reader can copy it and rerun what made the figures."""
import shlex
import sys


def quoted(args) -> str:
    """The arguments as one shell line, each quoted where the shell would split or expand it."""
    return " ".join(shlex.quote(str(a)) for a in args)


def invocation(program: str, argv=None) -> str:
    """`program` followed by the arguments it was given: `argv` when a caller passed them (an
    empty list included), else this process's own."""
    args = sys.argv[1:] if argv is None else argv
    return " ".join([program, quoted(args)]) if args else program
