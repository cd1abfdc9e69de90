#!/bin/bash
# test_help_json.sh GRANWAVE SRCDIR: `COMMAND --help --json` prints the help as
# one JSON document (granwave chain --help --json printed the text help,
# ignoring --json).
#  - For every command that `granwave --help` lists, `C --help --json` and
#    `C --json --help`: exit 0, nothing on stderr, stdout one JSON document
#    (Debian's python3 json) with the command's name and its usage line (the
#    text help's first line), whose options are exactly the flags the text
#    help lists, in its order, each with name, metavar, kind, unit, range,
#    min, max, default, choices and help, the help being the text help's
#    line; a range the help prints ("in [1e-6, 1]") is the range given (where
#    it prints none, a number option's is the parser's: test_help_json_ranges).
#  - `help C --json` prints what `C --help --json` prints; `granwave --help
#    --json` and `help --json` list exactly the commands of `granwave --help`.
#  - Nothing is written to disk (the runs' directory stays empty); --json
#    without --help on sweep (no --json of its own) is still refused, exit 2.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=test_lib.sh
. "$2/tests/test_lib.sh"
test_setup "$@"
export LC_ALL=C
mkdir "$tmp/run" && cd "$tmp/run" || exit 1

cmds=$("$GW" --help | sed -n '/^commands:/,$p' | sed -n 's/^  \([a-z-]*\) .*/\1/p')
[ "$(echo "$cmds" | wc -l)" -ge 10 ] && ok "granwave --help lists $(echo "$cmds" | wc -l) commands" ||
    ko "granwave --help lists: $cmds"
for c in $cmds; do
    "$GW" "$c" --help >"$tmp/text" 2>/dev/null
    for order in "--help --json" "--json --help"; do
        # shellcheck disable=SC2086
        "$GW" "$c" $order >"$tmp/json" 2>"$tmp/err"
        rc=$?
        if [ $rc -ne 0 ] || [ -s "$tmp/err" ]; then
            ko "$c $order: exit $rc, stderr: $(head -c 200 "$tmp/err")"; continue
        fi
        msg=$(/usr/bin/python3 - "$c" "$tmp/text" "$tmp/json" <<'PY'
import json, re, sys
cmd, text, js = sys.argv[1], open(sys.argv[2]).read().splitlines(), sys.argv[3]
try:
    d = json.load(open(js))
except ValueError as e:
    print("not JSON: %s" % e); sys.exit()
flags, helps = [], {}
for line in text[text.index("options:") + 1:]:
    m = re.match(r"^  --([a-z0-9-]+)(?: \S+)?\s+(.*)$", line)
    if m:
        flags.append(m.group(1)); helps[m.group(1)] = m.group(2)
keys = {"name", "metavar", "kind", "unit", "range", "min", "max", "default", "choices", "help"}
opts = d.get("options", [])
bad = []
if d.get("command") != cmd: bad.append("command %r" % d.get("command"))
if "usage: " + str(d.get("usage")) != text[0]: bad.append("usage %r" % d.get("usage"))
if [o.get("name") for o in opts] != flags: bad.append("flags %s, the text's %s" % ([o.get("name") for o in opts], flags))
for o in opts:
    if set(o) != keys: bad.append("%s: keys %s" % (o.get("name"), sorted(o)))
    elif helps.get(o["name"]) != o["help"]: bad.append("%s: help %r" % (o["name"], o["help"]))
    else:
        m = re.search(r"(?:^| )in ([\[(][^\])]*[\])])", o["help"])
        # where the line prints none, a number's range is the parser's (test_help_json_ranges)
        if m and m.group(1) != o["range"] or not m and o["range"] is not None and o["kind"] not in ("number", "integer"):
            bad.append("%s: range %r" % (o["name"], o["range"]))
print("; ".join(bad) if bad else "OK %d flags" % len(opts))
PY
)
        case $msg in OK*) ok "$c $order: one JSON document, ${msg#OK }" ;; *) ko "$c $order: $msg" ;; esac
    done
    "$GW" help "$c" --json >"$tmp/h" 2>&1
    "$GW" "$c" --help --json >"$tmp/j" 2>&1
    [ -s "$tmp/h" ] && cmp -s "$tmp/h" "$tmp/j" && ok "help $c --json is $c --help --json" ||
        ko "help $c --json differs: $(head -c 200 "$tmp/h")"
done
for form in "--help --json" "help --json"; do
    # shellcheck disable=SC2086
    "$GW" $form >"$tmp/list" 2>"$tmp/err"
    rc=$?
    got=$(/usr/bin/python3 -c "import json,sys; print(' '.join(c['name'] for c in json.load(open(sys.argv[1]))['commands']))" "$tmp/list" 2>&1)
    [ $rc -eq 0 ] && [ ! -s "$tmp/err" ] && [ "$got" = "$(echo $cmds)" ] && ok "granwave $form: the commands of --help" ||
        ko "granwave $form: exit $rc, $got"
done
"$GW" sweep --json >"$tmp/o" 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && grep -q "^granwave sweep: unknown option '--json'" "$tmp/err" && [ ! -s "$tmp/o" ] &&
    ok "sweep --json without --help: refused, exit 2" || ko "sweep --json: exit $rc, $(head -c 200 "$tmp/err")"
[ -z "$(ls -A "$tmp/run")" ] && ok "nothing written to disk" || ko "written: $(ls -A "$tmp/run" | tr '\n' ' ')"
test_summary test_help_json
