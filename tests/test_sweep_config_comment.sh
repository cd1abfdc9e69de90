#!/bin/bash
# test_sweep_config_comment.sh GRANWAVE SRCDIR: a '#' after a value in a sweep
# config (issue 18). The config reader (libinih) takes only ';' as an inline
# comment; '#' starts a comment only at the start of a line. A '#' that begins
# a value or follows a blank in it, where a ';' would start a comment, was
# read as part of the value: 'n = 4  # beads' was refused as "case 0: n: '4  #
# beads' is not an integer" (neither the line nor the cause), 'out = o  #
# where' made a directory 'o  # where' (exit 0), and a sample named 's #1.txt'
# ran. Such a value is now refused, in every section and on a list's continued
# lines: exit 2, one line naming the file, the line and the key, saying that
# '#' starts no comment there and ';' does; nothing written (a run or --check).
# 15 checks; on the code before, 9 fail (the message in 1 to 5, exit 0 and
# the directory made in 2, --check passing the sample in 5); the rest are
# 'nothing written' checks and two controls that the rule takes away nothing
# that worked (';' comments, '#' comment lines, a '#' inside a value).
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

# refused WHAT FILE LINE KEY [ARGS]: granwave sweep FILE ARGS exits 2 with one
# line naming FILE:LINE and KEY and saying '#' starts no comment, ';' does;
# the working directory holds afterwards what it held before
refused() {
    local what=$1 file=$2 line=$3 key=$4
    shift 4
    local before after
    before=$(ls -A | grep -v '^err\.txt$\|^out\.txt$' | sort)
    "$GW" sweep "$file" --quiet "$@" >out.txt 2>err.txt
    local rc=$?
    after=$(ls -A | grep -v '^err\.txt$\|^out\.txt$' | sort)
    local msg
    msg=$(head -c 300 err.txt)
    if [ $rc -eq 2 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -qF "$file:$line: $key: " err.txt &&
        grep -q "'#' after a value starts no comment in a config, ';' does" err.txt; then
        ok "$what: exit 2, $msg"
    else
        ko "$what: exit $rc, $msg"
    fi
    [ "$before" = "$after" ] && [ ! -s out.txt ] && ok "  nothing written" ||
        ko "  written: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
}

head_chain='[sweep]\nmodel = chain\nout = o\n'

# 1 a [grid] value followed by '# comment'
printf "$head_chain[grid]\nn = 4  # beads\nvimp = 0.1\n" >g.ini
refused "[grid] n = 4  # beads" g.ini 5 "[grid] n"
refused "  under --check" g.ini 5 "[grid] n" --check

# 2 [sweep] out followed by '# comment': before, a directory 'o  # where', exit 0
printf '[sweep]\nmodel = chain\nout = o  # where\n[grid]\nn = 2\n[params]\nt-max = 1e-4\n' >o.ini
refused "[sweep] out = o  # where" o.ini 3 "[sweep] out"
[ ! -e 'o  # where' ] && [ ! -e o ] && ok "  no directory 'o  # where' nor 'o'" || ko "  a directory made: $(ls -A | tr '\n' ' ')"

# 3 a [params] value, the '#' right after a tab
printf "$head_chain[grid]\nn = 2\n[params]\nt-max = 1e-4\t#s\n" >p.ini
refused "[params] t-max = 1e-4<TAB>#s" p.ini 7 "[params] t-max"

# 4 the continued line of a [grid] list
printf "$head_chain[grid]\nvimp = 0.1, 0.2,\n    0.3  # more\nn = 2\n" >c.ini
refused "a [grid] list's continued line '    0.3  # more'" c.ini 6 "[grid] vimp"

# 5 a value that names a file whose name holds ' #' (it ran before): refused
# too, so that no value is read otherwise than the config's author meant
"$GW" layer-make --n 30 --out 's #1.txt' >/dev/null 2>err.txt || { echo "FAIL: layer-make: $(head -c 200 err.txt)"; exit 1; }
printf '[sweep]\nmodel = layer\nout = l\n[grid]\npoint = 0\n[params]\nsample = s #1.txt\nt-max = 0.01\n' >l.ini
refused "[params] sample = s #1.txt (a file of that name exists)" l.ini 7 "[params] sample" --check

# controls: ';' after a value, '#' at the start of a line (indented too), after
# a section header and inside a value without a blank before it
printf '[sweep]   # the sweep\nmodel = chain  ; the model\nout = ok ; here\n# a comment\n[grid]\n  # indented\nn = 2 ; beads\nvimp = 0.1,\n  # between\n    0.2\n[params]\nt-max = 1e-4\n' >ok.ini
"$GW" sweep ok.ini --check >out.txt 2>err.txt
rc=$?
[ $rc -eq 0 ] && grep -q "ok.ini is valid: model chain, 2 cases" out.txt && ok "';' comments and '#' comment lines: --check exit 0, 2 cases" ||
    ko "';' comments and '#' comment lines: exit $rc, $(head -c 300 err.txt)"
printf '[sweep]\nmodel = layer\nout = l2\n[grid]\npoint = 0\n[params]\nsample = t#1.txt\nt-max = 0.01\n' >l2.ini
cp 's #1.txt' 't#1.txt'
"$GW" sweep l2.ini --check >out.txt 2>err.txt
rc=$?
[ $rc -eq 0 ] && ok "a '#' inside a value, no blank before it (sample = t#1.txt): --check exit 0" ||
    ko "sample = t#1.txt: exit $rc, $(head -c 300 err.txt)"

test_summary test_sweep_config_comment
