#!/bin/sh
# Doxygen input filter: the headers' // comments become /// (documenting what follows) and a
# trailing "; // ..." becomes "; ///< ..." (documenting the member before it). Comment text is
# plain prose, not Doxygen markup, so characters Doxygen would read as commands or HTML tags
# (\ @ < > & #) are escaped inside comments.
exec sed -E \
  -e '/^[[:space:]]*\/\/( |$)/{ s/[\\@<>&#%]/\\&/g; s/^([[:space:]]*)\/\/( |$)/\1\/\/\/\2/; }' \
  -e '/[;,][[:space:]]*\/\/ /{ h; s/^(.*[;,])[[:space:]]*\/\/ .*$/\1/; x; s/^.*[;,][[:space:]]*\/\/ //; s/[\\@<>&#%]/\\&/g; s/^/ \/\/\/< /; H; x; s/\n//; }' \
  "$1"
