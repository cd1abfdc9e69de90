#!/bin/bash
# bench_lib.sh: sourced by the bench scripts.
#   posint NAME VALUE: refuse anything but a positive integer, before any work
#   (exit 2, one line naming the script and NAME).
posint() {
    case "$2" in '' | *[!0-9]* | 0*)
        echo "$(basename "$0"): $1 must be a positive integer, got '$2'" >&2
        exit 2
        ;;
    esac
}
