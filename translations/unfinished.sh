#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# translations/unfinished.sh FILE.ts...: prints one "LANG: CONTEXT: SOURCE" line per message
# that is not translated (type="unfinished" or empty), and exits 1 when there is any.
# Used by scripts/update-translations.sh and the Translations.* ctest tests.
set -euo pipefail
perl -0777 -ne '
  my $lang = ($ARGV =~ /_([a-z]{2})\.ts$/) ? $1 : $ARGV;
  sub unxml { my $t = shift; $t =~ s/&lt;/</g; $t =~ s/&gt;/>/g; $t =~ s/&quot;/"/g;
              $t =~ s/&apos;/\x27/g; $t =~ s/&amp;/&/g; $t =~ s/\n/\\n/g; return $t; }
  while (/<context>\s*<name>(.*?)<\/name>(.*?)<\/context>/gs) {
    my ($ctx, $body) = ($1, $2);
    while ($body =~ /<message[^>]*>(.*?)<\/message>/gs) {
      my $m = $1;
      my ($src) = $m =~ /<source>(.*?)<\/source>/s;
      my ($attrs, $tr) = $m =~ /<translation([^>]*?)(?:\/>|>(.*?)<\/translation>)/s;
      $tr //= "";
      my $forms = $tr; $forms =~ s/<\/?numerusform>//g;
      if ($attrs =~ /type="(unfinished|vanished|obsolete)"/ || $forms =~ /^\s*$/) {
        print "$lang: $ctx: " . unxml($src) . "\n"; $n++;
      }
    }
  }
  END { exit($n ? 1 : 0) }
' "$@"
