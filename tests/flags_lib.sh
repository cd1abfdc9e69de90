#!/bin/bash
# flags_lib.sh: sourced by the tests that go over every numeric flag of every
# command (test_hostile_fortythird.sh, test_range_bounds.sh) after
# refusal_lib.sh and hostile_setup (GW set, the scratch directory entered):
#   flags_setup: the files the commands' base lines name (s20.txt, a
#   20-particle sample; results.csv, a measured sweep table; sw.ini, a chain
#   sweep), made in the current directory.
#   flag_base CMD: a command line of CMD that runs (or reaches its checks)
#   quickly, one word a line.
#   flag_without FLAG ARGS...: ARGS with FLAG and its value left out, one a line.
#   numeric_flags: "CMD FLAG LIST" for every flag that takes a value other than
#   a name, a file or a directory, of every command, found from its --help
#   (LIST 1 for a list flag "--F A,B.."); the studies' --radii (which they
#   refuse whatever its value) left out.

flags_setup() {
    make_sample s20.txt --n 20 --width-rm 8
    cp "$SRC/data/measured/layer_walls/results.csv" results.csv
    printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nsolver = rk4\n' >sw.ini
}

flag_base() {
    local line
    case $1 in
        chain) line="chain --n 2 --out o" ;;
        falcon) line="falcon --n 1:2 --heights none --quiet --jobs 1 --out o" ;;
        wavespeed) line="wavespeed --n 6:8 --vimp 0.3 --quiet --jobs 1 --out o" ;;
        softwall) line="softwall --n 1:3 --quiet --jobs 1 --out o" ;;
        drop) line="drop --n 2 --t-max 2e-4 --out o" ;;
        dispersion) line="dispersion --n 16 --t-samples 64 --out o" ;;
        layer-make) line="layer-make --n 10 --out o" ;;
        layer-impact) line="layer-impact --sample s20.txt --t-max 0.001 --quiet --out o" ;;
        layer-stats) line="layer-stats results.csv --out o" ;;
        sweep) line="sweep sw.ini --check --out o" ;;
    esac
    printf '%s\n' $line
}

flag_without() {
    local f=$1 skip=0 a
    shift
    for a in "$@"; do
        if [ $skip = 1 ]; then skip=0; continue; fi
        if [ "$a" = "$f" ]; then skip=1; continue; fi
        printf '%s\n' "$a"
    done
}

numeric_flags() {
    local c f list help
    help=$(mktemp)
    for c in chain falcon wavespeed softwall drop dispersion layer-make layer-impact layer-stats sweep; do
        "$GW" "$c" --help >"$help" 2>&1
        for f in $(grep -E '^ +--[a-z-]+ [A-Z]' "$help" |
            grep -vE '^ +--[a-z-]+ (NAME|FILE|DIR|LAW|MODEL|HOW|KIND|WHAT|LIST) ' | awk '{print $1}'); do
            case "$c $f" in falcon\ --radii | wavespeed\ --radii | softwall\ --radii) continue ;; esac
            list=0
            grep -qE "^ +$f [A-Z]+,[A-Z]+\.\." "$help" && list=1
            echo "$c $f $list"
        done
    done
    rm -f "$help"
}
