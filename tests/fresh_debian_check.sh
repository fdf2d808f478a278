#!/usr/bin/env bash
# The fresh-machine check: ./test.sh from a clean clone inside a brand-new minimal Debian 12 root,
# so that a package missing from third_party/debian_packages.sh (or a tool that only happens to be
# installed on a developer's machine) fails here rather than on a contributor's first run.
#
# Usage, as root on a Debian or Ubuntu host with network access to deb.debian.org:
#   tests/fresh_debian_check.sh ROOT_DIR [COMMIT]
# ROOT_DIR must not exist yet (or be a root this script made earlier, which is reused as is) and
# must lie outside the repository. COMMIT (default HEAD) is cloned from this repository, so only
# committed work is tested. Needs debootstrap and git on the host.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 ROOT_DIR [COMMIT]" >&2
  exit 1
fi
root=$(realpath -m "$1")
commit=${2:-HEAD}
repo=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
case "$root/" in
  "$repo"/*) echo "$0: ROOT_DIR must lie outside the repository" >&2; exit 1 ;;
esac
if [[ "$(id -u)" -ne 0 ]]; then
  echo "$0: debootstrap, mount and chroot need root" >&2
  exit 1
fi

if [[ ! -x "$root/bin/bash" ]]; then
  time debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
# A host behind a TLS-inspecting proxy trusts the proxy's certificate authority through its own
# local certificates (/usr/local/share/ca-certificates); the root gets the same ones, which
# ca-certificates adds to its bundle when ./test.sh installs it, and Node.js (npm, for the glTF
# validator) is pointed at that bundle as the host's is. Without a proxy there is nothing to copy.
local_cas=(/usr/local/share/ca-certificates/*.crt)
node_ca_env=()
if [[ -e "${local_cas[0]}" ]]; then
  mkdir -p "$root/usr/local/share/ca-certificates"
  cp "${local_cas[@]}" "$root/usr/local/share/ca-certificates/"
  node_ca_env=(NODE_EXTRA_CA_CERTS=/etc/ssl/certs/ca-certificates.crt)
fi

mounted=()
unmount_all() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" || true; done
}
trap unmount_all EXIT
# Binds left by an earlier run that was killed (no EXIT trap runs on SIGKILL) are reused and undone
# at this run's end too: a root left with the host's /dev bound inside is a trap, since deleting the
# root with a plain `rm -rf` then deletes the host's device files.
for dir in proc sys dev dev/pts; do
  mountpoint -q "$root/$dir" || mount --bind "/$dir" "$root/$dir"
  mounted+=("$root/$dir")
done

# A root made earlier already has ca-certificates: its bundle is made again with the copied ones.
if [[ ${#node_ca_env[@]} -gt 0 && -x "$root/usr/sbin/update-ca-certificates" ]]; then
  chroot "$root" /usr/sbin/update-ca-certificates >/dev/null
fi

rm -rf "$root/root/rgbsub"
git clone --quiet --no-hardlinks "$repo" "$root/root/rgbsub"
git -C "$root/root/rgbsub" checkout --quiet --detach "$commit"
echo "=== ./test.sh in $root at $(git -C "$root/root/rgbsub" rev-parse --short HEAD)"
time chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 "${node_ca_env[@]}" \
  /bin/bash -c 'cd /root/rgbsub && ./test.sh'
