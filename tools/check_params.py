"""Check a whole-book parameter file before a build: one line naming the file and the
problem (unknown section or parameter, a value that is not a number, a missing file),
exit status 2; nothing is built from a file every page would reject."""

import sys


def main(argv=None):
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: check_params.py FILE.toml", file=sys.stderr)
        return 2
    from magbench.chapters import read_overrides
    from magbench.io import DataError

    try:
        read_overrides(args[0])
    except DataError as exc:
        print(f"make: PARAMS: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
