# Sourced by .ci/setup and .ci/setup-meshlab2025: downloads pinned by sha256, so that every setup
# gets the same bytes or stops with a message saying which file it could not get.

# The URI of the machine's own Debian archive (its 'deb' entry for bookworm main), so that
# downloads go where apt goes (a local mirror or proxy); deb.debian.org when there is none.
debian_archive() {
  local uri=""
  if ls /etc/apt/sources.list.d/*.sources >/dev/null 2>&1; then
    uri=$(awk '
      BEGIN { RS = ""; FS = "\n" }
      {
        types = ""; uris = ""; suites = ""; comps = ""
        for (i = 1; i <= NF; i++) {
          line = $i
          if (line ~ /^Types:/)      { types = " " line " " }
          if (line ~ /^URIs:/)       { sub(/^URIs:[ \t]*/, "", line); split(line, u, " "); uris = u[1] }
          if (line ~ /^Suites:/)     { sub(/^Suites:[ \t]*/, "", line); suites = " " line " " }
          if (line ~ /^Components:/) { comps = " " line " " }
        }
        if (types ~ / deb / && suites ~ / bookworm / && comps ~ / main / && uris != "") { print uris; exit }
      }' /etc/apt/sources.list.d/*.sources)
  fi
  if [ -z "$uri" ]; then
    uri=$(grep -hE '^deb (\[[^]]*\] )?[^ ]+ bookworm .*main' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
          sed -E 's/^deb (\[[^]]*\] )?([^ ]+) .*/\2/' | head -n1 || true)
  fi
  uri="${uri:-http://deb.debian.org/debian}"
  echo "${uri%/}"
}

# fetch_pinned PATH SHA256 URL...: downloads the file from the first URL that serves it with that
# sha256 and saves it as PATH; nothing is left at PATH otherwise, and the call fails.
fetch_pinned() {
  local path=$1 sha256=$2 url got
  shift 2
  for url in "$@"; do
    rm -f "$path.part"
    if ! curl -fsSL --connect-timeout 30 --retry 2 -o "$path.part" "$url" 2>"$path.err"; then
      echo "${0##*/}: $url: $(tail -n1 "$path.err")" >&2
      continue
    fi
    got=$(sha256sum "$path.part" | cut -d' ' -f1)
    if [ "$got" = "$sha256" ]; then
      rm -f "$path.err" && mv "$path.part" "$path"
      return 0
    fi
    echo "${0##*/}: $url: sha256 $got, expected $sha256" >&2
  done
  rm -f "$path.part" "$path.err"
  echo "${0##*/}: cannot get ${path##*/} with sha256 $sha256 from any of: $*" >&2
  return 1
}
