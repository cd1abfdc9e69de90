#!/bin/bash
# test_out_replaced.sh GRANWAVE SRCDIR: an --out directory moved, removed or
# replaced while a run writes into it (issue 18, the thirtieth hostile pass).
# layer-impact --out D stages its files as temporaries in D from its first
# snapshot on and places them together at the end (gw_io_outset.c). When D is
# swapped under it, the set now finds at its commit that D no longer names
# the directory it began in: exit 1, one line naming D and saying so, nothing
# placed, and its temporaries removed where they are (through the directory
# it holds open). Before, it said "its temporary ... is gone" (they were not:
# the directory had moved) and left them in the moved directory.
# Each run is swapped once a temporary exists in D (wait_file, no sleep),
# with about a second of the run still to go:
#  1 mv D D.old; mkdir D: exit 1, the message, D.old holds what D held before
#    the run (one file of the user's) and nothing else, the new D is empty;
#  2 rm -rf D; mkdir D: the same, D empty;
#  3 mv D D.old; ln -s T D (a link to another directory): the same, T empty;
#  4 mv D D.old; a regular file D: exit 1 naming D, D.old as before;
#  5 mv D D.old; ln -s D.old D (the same directory under a link): exit 0,
#    the run's files in D.old beside the user's, no temporary.
# 13 checks; on the code before, 6 fail (the temporaries left in D.old in 1,
# 3 and 4, the message in 1 to 3).
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C
"$GW" layer-make --n 60 --out s.txt >/dev/null 2>err.txt || { echo "FAIL: layer-make: $(head -c 200 err.txt)"; exit 1; }

# swap WHAT ACTION: layer-impact into D (holding the user's mine.txt), ACTION
# run once a temporary of the run exists in D; sets rc and err.txt
swap() {
    rm -rf D D.old T
    mkdir D && echo keep >D/mine.txt
    "$GW" layer-impact --sample s.txt --t-max 0.5 --full --quiet --out D >/dev/null 2>err.txt &
    local pid=$!
    if wait_file $pid 'D/*.tmp.*'; then
        eval "$2"
    else
        echo "  ($1: the run ended before a temporary was seen)"
    fi
    wait $pid
    rc=$?
}

# only_mine DIR: DIR holds the user's file and nothing else
only_mine() { [ "$(ls -A "$1" 2>/dev/null)" = mine.txt ]; }
# (one line besides the run's warnings: since session 46 a crown speed nulled for
# its scatter is warned of)
said_moved() { [ "$(grep -vc "warning: " err.txt)" -eq 1 ] && grep -q "^granwave layer-impact --out: D: the output directory was moved, removed or replaced while the run went on: nothing placed" err.txt; }

swap "moved" 'mv D D.old && mkdir D'
[ $rc -eq 1 ] && said_moved && ok "moved: exit 1, $(cut -c1-150 err.txt)" || ko "moved: exit $rc, $(head -c 300 err.txt)"
only_mine D.old && ok "  D.old holds the user's file only" || ko "  D.old holds $(ls -A D.old | tr '\n' ' ')"
[ -z "$(ls -A D)" ] && ok "  the new D is empty" || ko "  the new D holds $(ls -A D | tr '\n' ' ')"

swap "removed and made again" 'rm -rf D && mkdir D'
[ $rc -eq 1 ] && said_moved && ok "removed and made again: exit 1, the message" || ko "removed and made again: exit $rc, $(head -c 300 err.txt)"
[ -z "$(ls -A D)" ] && ok "  D is empty" || ko "  D holds $(ls -A D | tr '\n' ' ')"

swap "a link to another directory" 'mv D D.old && mkdir T && ln -s T D'
[ $rc -eq 1 ] && said_moved && ok "replaced by a link to another directory: exit 1, the message" ||
    ko "replaced by a link to another directory: exit $rc, $(head -c 300 err.txt)"
only_mine D.old && ok "  D.old holds the user's file only" || ko "  D.old holds $(ls -A D.old | tr '\n' ' ')"
[ -z "$(ls -A T)" ] && ok "  the link's directory is empty" || ko "  T holds $(ls -A T | tr '\n' ' ')"

swap "a file" 'mv D D.old && echo x >D'
[ $rc -eq 1 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "D" err.txt && ok "replaced by a file: exit 1, $(cut -c1-120 err.txt)" ||
    ko "replaced by a file: exit $rc, $(head -c 300 err.txt)"
only_mine D.old && ok "  D.old holds the user's file only" || ko "  D.old holds $(ls -A D.old | tr '\n' ' ')"
[ "$(cat D)" = x ] && ok "  the file D as it was" || ko "  the file D changed"

swap "the same directory under a link" 'mv D D.old && ln -s D.old D'
[ $rc -eq 0 ] && ok "the same directory under a link: exit 0" || ko "the same directory under a link: exit $rc, $(head -c 300 err.txt)"
got=$(ls -A D.old | tr '\n' ' ')
[ -s D.old/impact.json ] && [ -f D.old/mine.txt ] && ! ls -A D.old | grep -q '\.tmp\.' &&
    ok "  its files placed there beside the user's ($got)" || ko "  D.old holds $got"

test_summary test_out_replaced
