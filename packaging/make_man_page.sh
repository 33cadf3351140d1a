#!/usr/bin/env bash
# Writes a man page from a program's own --help (and, for a program with subcommands, each
# subcommand's --help), so that the page cannot drift from the program.
# Usage: make_man_page.sh PROGRAM NAME VERSION OUT.1
set -euo pipefail
program=$1 name=$2 version=$3 out=$4

# roff: backslashes doubled, a leading dot or quote escaped, each line kept as it is.
roff_verbatim() {
  sed -e 's/\\/\\e/g' -e "s/^\\([.']\\)/\\\\\\&\\1/"
}

help=$("$program" --help | sed "s|$program|$name|g")
summary=${help%%$'\n'*}  # the first line, without a pipe whose reader may close it early
{
  printf '.TH %s 1 "" "%s %s" "User Commands"\n' "$(printf '%s' "$name" | tr '[:lower:]' '[:upper:]')" "$name" "$version"
  printf '.SH NAME\n%s \\- %s\n' "$name" "$(printf '%s' "$summary" | sed 's/^[^:]*: //' | roff_verbatim)"
  printf '.SH DESCRIPTION\n.nf\n'
  printf '%s\n' "$help" | roff_verbatim
  printf '.fi\n'
  commands=$(printf '%s\n' "$help" | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }')
  if [ -n "$commands" ]; then
    printf '.SH COMMANDS\n'
    for command in $commands; do
      printf '.SS %s %s\n.nf\n' "$name" "$command"
      "$program" "$command" --help | sed "s|$program|$name|g" | roff_verbatim
      printf '.fi\n'
    done
  fi
  printf '.SH SEE ALSO\n'
  if [ "$name" = isurface ]; then printf 'isurface-cli(1)\n'; else printf 'isurface(1)\n'; fi
} > "$out.tmp"
mv "$out.tmp" "$out"
