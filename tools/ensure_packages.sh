#!/usr/bin/env bash
# Installs the Debian packages a make target needs, when missing (the Makefile's
# $(call ensure_packages,<path:package pairs>) runs this; ports/web/web.mk and
# ports/cortex-m/mcu.mk call it the same way).
#
# Usage: tools/ensure_packages.sh /usr/bin/cmake:cmake /usr/include/doctest/doctest.h:doctest-dev ...
# Each argument is "file:package": the package is missing when the file is. Missing packages
# are installed with apt-get when run as root (waiting up to APT_LOCK_TIMEOUT seconds, 600 by
# default, for another apt-get to release the lock); otherwise the one apt-get line to run is
# printed and the exit status is 1.
set -u
missing=""
for pair in "$@"; do
  file=${pair%%:*}
  package=${pair##*:}
  [ -f "$file" ] || case " $missing " in *" $package "*) ;; *) missing="$missing $package" ;; esac
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ] && command -v apt-get > /dev/null 2>&1; then
  lock="DPkg::Lock::Timeout=${APT_LOCK_TIMEOUT:-600}"
  echo "shitsukan: installing$missing (apt-get)"
  # shellcheck disable=SC2086  # $missing is a list of package names
  if apt-get -o "$lock" update -qq > /dev/null &&
     DEBIAN_FRONTEND=noninteractive apt-get -o "$lock" install -y -qq $missing > /dev/null; then
    exit 0
  fi
  echo "shitsukan: apt-get install$missing failed"
  exit 1
fi
echo "shitsukan: missing packages:$missing -- run: sudo apt-get install$missing"
exit 1
