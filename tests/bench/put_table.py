"""Put a benchmark's table into a document, between its markers <!-- bench:NAME --> and
<!-- /bench:NAME --> (the table carries them); where the document has none yet, before HEADING.
    python3 tests/bench/put_table.py DOC NAME HEADING TABLE"""
import re
import sys


def main():
    doc, name, heading, table = sys.argv[1:5]
    s = open(doc).read()
    start, end = f"<!-- bench:{name} -->", f"<!-- /bench:{name} -->"
    if start in s:
        s = re.sub(re.escape(start) + ".*?" + re.escape(end), lambda m: table, s, flags=re.S)
    else:
        s = s.replace(heading, table + "\n\n" + heading)
    open(doc, "w").write(s)


if __name__ == "__main__":
    main()
