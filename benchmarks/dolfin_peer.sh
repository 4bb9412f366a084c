# Sourced by the benchmarks that run a legacy-DOLFIN peer
# (natural_shape_vs_dolfin.sh, plate_buckling_vs_dolfin.sh): installs
# Debian's python3-dolfin if it is missing, as scripts/setup.sh installs
# the suite's packages (sudo -n when not root: no prompt without stdin).
ensure_dolfin() {
  local status
  status="$(dpkg-query -W -f='${Status}' python3-dolfin 2>/dev/null || true)"
  [[ "$status" == "install ok installed" ]] && return 0
  local sudo=()
  [[ "$(id -u)" -ne 0 ]] && sudo=(sudo -n)
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q python3-dolfin </dev/null >/dev/null
}
