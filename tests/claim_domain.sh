# Sourced by test and benchmark scripts (POSIX sh). claim_domain VAR FD [OFFSET] sets VAR to a
# DDS domain 1-200 that no other test process holds: the first free one from
# 1 + ($$ + OFFSET) % 200 on, as test_domain() in tests/service/service_process.cc claims its
# own (the same lock files). The claim is an flock on file descriptor FD (3-9), held by this
# shell and inherited by the programs it starts, until they all exit.
claim_domain() {
  _claim_dir=${TMPDIR:-/tmp}/gearcoupling-test-domains
  mkdir -p "$_claim_dir" && chmod 1777 "$_claim_dir" 2>/dev/null || true
  _claim_i=0
  while [ "$_claim_i" -lt 200 ]; do
    _claim_d=$((1 + ($$ + ${3:-0} + _claim_i) % 200))
    # Opened in a subshell first: a redirection that fails on `exec` ends a POSIX shell.
    if (: >>"$_claim_dir/$_claim_d") 2>/dev/null && eval "exec $2<>\"\$_claim_dir/\$_claim_d\"" &&
      flock -n "$2"; then
      eval "$1=\$_claim_d"
      return 0
    fi
    _claim_i=$((_claim_i + 1))
  done
  eval "$1=\$((1 + (\$\$ + \${3:-0}) % 200))"   # every domain held: the pid's, as before
}
