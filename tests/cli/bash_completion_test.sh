#!/usr/bin/env bash
# The bash completion script of `vantage completion bash` (its path is $1): completing a few
# command lines gives the words the CLI's option table holds. Exit 1 naming the first that does
# not.
set -u
source "$1"

# complete WORDS... : the completions of the last word.
complete_line() {
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _vantage
  printf '%s\n' "${COMPREPLY[@]}"
}

expect() {
  local want=$1
  shift
  if ! complete_line "$@" | grep -qx -- "$want"; then
    echo "completing '$*' does not offer '$want': $(complete_line "$@" | tr '\n' ' ')" >&2
    exit 1
  fi
}

expect_not() {
  local unwanted=$1
  shift
  if complete_line "$@" | grep -qx -- "$unwanted"; then
    echo "completing '$*' offers '$unwanted'" >&2
    exit 1
  fi
}

expect place vantage pl
expect layout vantage lay
expect snap vantage layout sn
expect --distances vantage place --dis
expect --marker-diameter vantage layout snap --mark
expect --json vantage place body.obj --markers 4 --j
expect_not --distances vantage analyze --dis

echo "bash completion: ok"
