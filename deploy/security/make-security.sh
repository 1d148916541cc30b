#!/usr/bin/env bash
# Makes everything DDS Security needs for a gearcoupling test cell (docs/security.md):
#
#   bash deploy/security/make-security.sh OUT_DIR [--service NAME]... [--client NAME]...
#        [--dashboard NAME]... [--console NAME]... [--monitor NAME]... [--cell NAME]...
#        [--operator NAME --cells CELL[,CELL]...]...
#        [--revoke IDENTITY]... [--days N]
#
#   OUT_DIR/ca/identity_ca.pem, permissions_ca.pem    the two CA certificates (every host)
#   OUT_DIR/ca/*_key.pem                              the CA keys (stay on the CA machine)
#   OUT_DIR/ca/identity_crl.pem                       revoked identities, signed (every host)
#   OUT_DIR/ca/identity_db/                           the identity CA's openssl database
#   OUT_DIR/governance.xml, governance.p7s            domain rules, S/MIME-signed (every host)
#   OUT_DIR/<identity>/cert.pem, key.pem              the identity (only that host)
#   OUT_DIR/<identity>/permissions.xml, .p7s          what it may publish and read, signed
#   OUT_DIR/<identity>/security.xml                   Cyclone <Security> fragment naming the above
#   OUT_DIR/{client,console}-<NAME>/client_id_prefix  8 hex digits: the client's ids start with them
#
# Identities: "service-<NAME>" (default one: service-main), "client-<NAME>" (default: client-cell),
# "dashboard-<NAME>" (default: dashboard-main); "console-<NAME>", a dashboard whose query panel
# may ask the service (a dashboard's and a client's rights); the live test cell's "monitor-<NAME>",
# "cell-<NAME>" and "operator-<NAME>" (none by default); cell-<NAME> publishes only test cell
# NAME's measurements, operator-<NAME> swaps the models of only the test cells its --cells lists
# (each live test cell has its own partition, gearcoupling.live.cell.<CELL>: docs/protocol.md).
# --revoke IDENTITY puts that identity's certificate on the CRL for good (every security.xml names
# the CRL). Idempotent: what exists and is still valid is kept (keys, certificates, signatures,
# the CRL), so a second run changes no byte; a document is signed again only when its content changes, a certificate is made again
# only when it no longer verifies, the CRL only when the revoked set changes or it nears expiry.
set -euo pipefail

usage() { sed -n '2,28p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
fail() { echo "make-security.sh: $*" >&2; exit 1; }

LIB_DIR="${GC_DDS_SECURITY_LIB_DIR:-/usr/lib/x86_64-linux-gnu/libddsc0debian}"
# The protocol's names (protocol/names.cc): every request and reply topic matches these.
REQUEST_TOPICS="gearcoupling/*/request"
REPLY_TOPICS="gearcoupling/*/reply"
STATUS_TOPIC="gearcoupling/status"
STATUS_PARTITION="gearcoupling"
# The live test cell's names (live/live_names.h): health and residuals in partition
# "gearcoupling.live"; measurements and model swaps of test cell CELL in "gearcoupling.live.cell.CELL".
LIVE_PARTITION="gearcoupling.live"
CELL_PARTITION_PREFIX="gearcoupling.live.cell."
OPERATOR_PARTITION_PREFIX="gearcoupling.live.operator."
MEASUREMENT_TOPIC="gearcoupling/live/measurement"
RESIDUAL_TOPIC="gearcoupling/live/residual"
HEALTH_TOPIC="gearcoupling/live/health"
MODEL_TOPIC="gearcoupling/live/model"
PROPOSAL_TOPIC="gearcoupling/live/proposal"
MONITOR_STATUS_TOPIC="gearcoupling/live/monitor"
SUBJECT_BASE="C=NL,O=gearcoupling"

# ---- arguments --------------------------------------------------------------------------------
[ $# -ge 1 ] || usage
case "$1" in -h|--help) usage ;; esac
OUT="$1"; shift
SERVICES=(); CLIENTS=(); DASHBOARDS=(); CONSOLES=(); MONITORS=(); CELLS=(); OPERATORS=(); REVOKED=(); DAYS=3650
declare -A OPERATOR_CELLS=()
ROLES="service|client|dashboard|console|monitor|cell|operator"
valid_name() { [[ "$1" =~ ^[a-z0-9][a-z0-9_-]{0,31}$ ]] || fail "$2 \"$1\": allowed 1-32 of a-z 0-9 _ -, starting with a letter or digit"; }
# A --cells list: test cell names (live/live_names.h: 1-64 of A-Z a-z 0-9 . _ -), comma-separated.
valid_cells() {
  local cell
  [ -n "$1" ] || fail "--cells \"\": allowed CELL[,CELL]..., each 1-64 of A-Z a-z 0-9 . _ -"
  IFS=, read -ra cells <<<"$1"
  [[ "$1" != *, ]] || fail "--cells \"$1\": an empty test cell name; allowed CELL[,CELL]..., each 1-64 of A-Z a-z 0-9 . _ -"
  for cell in "${cells[@]}"; do
    [[ "$cell" =~ ^[A-Za-z0-9._-]{1,64}$ ]] \
      || fail "--cells \"$1\": test cell \"$cell\" not allowed; allowed CELL[,CELL]..., each 1-64 of A-Z a-z 0-9 . _ -"
  done
}
valid_identity() {
  [[ "$1" =~ ^($ROLES)-[a-z0-9][a-z0-9_-]{0,31}$ ]] \
    || fail "--revoke \"$1\": allowed an identity ROLE-NAME, ROLE one of ${ROLES//|/ }"
}
while [ $# -gt 0 ]; do
  [ $# -ge 2 ] || fail "$1 needs a value"
  case "$1" in
    --service) valid_name "$2" --service; SERVICES+=("$2") ;;
    --client) valid_name "$2" --client; CLIENTS+=("$2") ;;
    --dashboard) valid_name "$2" --dashboard; DASHBOARDS+=("$2") ;;
    --console) valid_name "$2" --console; CONSOLES+=("$2") ;;
    --monitor) valid_name "$2" --monitor; MONITORS+=("$2") ;;
    --cell) valid_name "$2" --cell; CELLS+=("$2") ;;
    --operator) valid_name "$2" --operator; OPERATORS+=("$2") ;;
    --cells) [ ${#OPERATORS[@]} -gt 0 ] || fail "--cells \"$2\": allowed only after --operator NAME (the test cells that operator may swap)"
             valid_cells "$2"; OPERATOR_CELLS[${OPERATORS[-1]}]="$2" ;;
    --revoke) valid_identity "$2"; REVOKED+=("$2") ;;
    --days) [[ "$2" =~ ^[0-9]+$ ]] && [ "$2" -ge 1 ] && [ "$2" -le 36500 ] \
              || fail "--days \"$2\": allowed an integer in [1, 36500]"; DAYS="$2" ;;
    *) fail "unknown argument \"$1\" (see --help)" ;;
  esac
  shift 2
done
[ ${#SERVICES[@]} -gt 0 ] || SERVICES=(main)
[ ${#CLIENTS[@]} -gt 0 ] || CLIENTS=(cell)
[ ${#DASHBOARDS[@]} -gt 0 ] || DASHBOARDS=(main)
for name in ${OPERATORS[@]+"${OPERATORS[@]}"}; do
  [ -n "${OPERATOR_CELLS[$name]:-}" ] \
    || fail "--operator $name: needs --cells CELL[,CELL]... after it (the test cells it may swap)"
done
for lib in auth ac crypto; do
  [ -f "$LIB_DIR/libdds_security_$lib.so" ] \
    || fail "$LIB_DIR/libdds_security_$lib.so missing: install Debian's libddsc0 (cyclonedds) or set GC_DDS_SECURITY_LIB_DIR"
done
command -v openssl >/dev/null || fail "openssl not found"
mkdir -p "$OUT/ca"
OUT="$(cd "$OUT" && pwd)"
umask 077  # keys are written readable by their owner only

# ---- helpers ----------------------------------------------------------------------------------
# Writes stdin to $1 only when the content differs, so unchanged files keep their bytes and time.
write_if_changed() {
  local tmp; tmp="$(mktemp "$1.XXXXXX")"
  cat >"$tmp"
  if [ -f "$1" ] && cmp -s "$tmp" "$1"; then rm -f "$tmp"; else chmod 644 "$tmp"; mv "$tmp" "$1"; fi
}

# make_ca NAME CN USAGE: a self-signed EC P-256 CA, kept when its key and certificate exist.
make_ca() {
  local key="$OUT/ca/$1_key.pem" cert="$OUT/ca/$1.pem"
  if [ -f "$key" ] && [ -f "$cert" ] && openssl x509 -in "$cert" -noout -checkend 86400 >/dev/null; then return; fi
  openssl ecparam -name prime256v1 -genkey -noout -out "$key"
  openssl req -new -x509 -key "$key" -out "$cert" -days "$DAYS" -sha256 \
    -subj "/${SUBJECT_BASE//,//}/CN=$2" \
    -addext "basicConstraints=critical,CA:TRUE" -addext "keyUsage=critical,$3"
  chmod 644 "$cert"
}

# Subject of identity $1 in the RFC 2253 order Cyclone's access control prints a certificate's
# subject in (X509_NAME_print_ex, XN_FLAG_RFC2253: last component first).
subject_of() { echo "CN=$1,${SUBJECT_BASE#C=NL,},C=NL"; }
# The same subject for openssl -subj.
subj_arg() { echo "/${SUBJECT_BASE//,//}/CN=$1"; }

# make_identity ID: key and certificate signed by the identity CA, kept while they still verify,
# match the wanted subject and the key.
make_identity() {
  local dir="$OUT/$1" key="$OUT/$1/key.pem" cert="$OUT/$1/cert.pem"
  mkdir -p "$dir"
  if [ -f "$key" ] && [ -f "$cert" ] \
     && openssl verify -CAfile "$OUT/ca/identity_ca.pem" "$cert" >/dev/null 2>&1 \
     && openssl x509 -in "$cert" -noout -checkend 86400 >/dev/null \
     && [ "$(openssl x509 -in "$cert" -noout -subject -nameopt RFC2253 | sed 's/^subject=//')" = "$(subject_of "$1")" ] \
     && [ "$(openssl x509 -in "$cert" -noout -pubkey)" = "$(openssl ec -in "$key" -pubout 2>/dev/null)" ]; then
    return
  fi
  openssl ecparam -name prime256v1 -genkey -noout -out "$key"
  openssl req -new -key "$key" -subj "$(subj_arg "$1")" -out "$dir/cert.csr"
  openssl x509 -req -in "$dir/cert.csr" -CA "$OUT/ca/identity_ca.pem" -CAkey "$OUT/ca/identity_ca_key.pem" \
    -CAcreateserial -out "$cert" -days "$DAYS" -sha256 \
    -extfile <(printf 'basicConstraints=critical,CA:FALSE\nkeyUsage=critical,digitalSignature,keyAgreement\n') 2>/dev/null
  rm -f "$dir/cert.csr"
  chmod 644 "$cert"
}

# sign DOC: DOC.p7s = DOC.xml S/MIME-signed by the permissions CA (clear-signed, -text, as DDS
# Security requires), unless the signature still verifies for the current text.
sign() {
  local xml="$1.xml" p7s="$1.p7s" verified
  if [ -f "$p7s" ] && verified="$(openssl smime -verify -in "$p7s" -CAfile "$OUT/ca/permissions_ca.pem" -text 2>/dev/null | tr -d '\r')" \
     && [ "$verified" = "$(cat "$xml")" ]; then
    return
  fi
  openssl smime -sign -in "$xml" -text -out "$p7s.tmp" -signer "$OUT/ca/permissions_ca.pem" \
    -inkey "$OUT/ca/permissions_ca_key.pem"
  chmod 644 "$p7s.tmp"; mv "$p7s.tmp" "$p7s"
}

# Permissions are valid as long as the permissions CA (fixed dates, so a rerun writes the same).
ca_date() { date -u -d "$(openssl x509 -in "$OUT/ca/permissions_ca.pem" -noout "-$1" | cut -d= -f2)" +%Y-%m-%dT%H:%M:%S; }

# criteria KIND TOPIC PARTITION...: one <publish> or <subscribe> block.
criteria() {
  local kind="$1" topic="$2"; shift 2
  echo "        <$kind>"
  echo "          <topics><topic>$topic</topic></topics>"
  echo -n "          <partitions>"; for p in "$@"; do echo -n "<partition>$p</partition>"; done; echo "</partitions>"
  echo "        </$kind>"
}

# grant ID RULES...: permissions document of identity ID; rules come from stdin.
permissions_doc() {
  cat <<XML
<?xml version="1.0" encoding="UTF-8"?>
<!-- Made by deploy/security/make-security.sh: what $1 may publish and read. default DENY: any
     topic or partition not allowed below is refused, locally and by every remote participant. -->
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-Security/20170801/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="$1">
      <subject_name>$(subject_of "$1")</subject_name>
      <validity><not_before>$(ca_date startdate)</not_before><not_after>$(ca_date enddate)</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>230</max></id_range></domains>
$(cat)
      </allow_rule>
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
XML
}

service_rules() {
  criteria subscribe "$REQUEST_TOPICS" "gearcoupling.request.*"
  criteria publish "$REPLY_TOPICS" "gearcoupling.reply.*"
  criteria publish "$STATUS_TOPIC" "$STATUS_PARTITION"
}

# hex_digits N: a pattern matching N lower-case hex digits and nothing else.
hex_digits() { local i; for ((i = 0; i < $1; i++)); do echo -n "[0-9a-f]"; done; }

# A client's replies: only partitions gearcoupling.reply.<prefix><8 more hex digits>. Character
# classes, not "*": a reader asking for a wildcard partition ("gearcoupling.reply.*", or "*" in
# the last 8 digits) is refused, since "*" is not a hex digit.
client_rules() {
  criteria publish "$REQUEST_TOPICS" "gearcoupling.request.$(hex_digits 16)"
  criteria subscribe "$REPLY_TOPICS" "gearcoupling.reply.$1$(hex_digits 8)"
  criteria subscribe "$STATUS_TOPIC" "$STATUS_PARTITION"
}

# What the monitor says beside the health: its proposals and its own status with the audit trail
# of swaps (issue 25). Read by dashboards, consoles and operators; published by the monitor alone.
learning_view_rules() {
  criteria subscribe "$PROPOSAL_TOPIC" "$LIVE_PARTITION"
  criteria subscribe "$MONITOR_STATUS_TOPIC" "$LIVE_PARTITION"
}

# What a dashboard shows of the live test cells: the monitor's health and residuals (issue 12),
# its proposals and audit trail (issue 25).
live_view_rules() {
  criteria subscribe "$HEALTH_TOPIC" "$LIVE_PARTITION"
  criteria subscribe "$RESIDUAL_TOPIC" "$LIVE_PARTITION"
  learning_view_rules
}

# The dashboard reads: the status and the live view.
dashboard_rules() {
  criteria subscribe "$STATUS_TOPIC" "$STATUS_PARTITION"
  live_view_rules
}

# A console: a dashboard whose query panel asks the service, so a client (prefix $1) as well.
console_rules() {
  client_rules "$1"
  live_view_rules
}

# The monitor (gearcoupling-monitor): reads measurements and model swaps of every test cell (its
# readers ask for the partition "gearcoupling.live.cell.*", which this pattern admits as a name,
# and for the older shared one), publishes the health and residuals. It sends no requests.
monitor_rules() {
  criteria subscribe "$MEASUREMENT_TOPIC" "$LIVE_PARTITION" "${CELL_PARTITION_PREFIX}*"
  criteria subscribe "$MODEL_TOPIC" "$LIVE_PARTITION" "${CELL_PARTITION_PREFIX}*"
  criteria publish "$HEALTH_TOPIC" "$LIVE_PARTITION"
  criteria publish "$RESIDUAL_TOPIC" "$LIVE_PARTITION"
  criteria publish "$PROPOSAL_TOPIC" "$LIVE_PARTITION"
  criteria publish "$MONITOR_STATUS_TOPIC" "$LIVE_PARTITION"
}

# The measurement side of test cell $1: gearcoupling replay (a DAQ) publishes in the cell's own
# partition only; gearcoupling record reads it (and the older shared partition, where under
# security nobody may publish measurements).
cell_rules() {
  criteria publish "$MEASUREMENT_TOPIC" "$CELL_PARTITION_PREFIX$1"
  criteria subscribe "$MEASUREMENT_TOPIC" "$LIVE_PARTITION" "$CELL_PARTITION_PREFIX$1"
}

# Operator $1 of test cells $2 (comma-separated): gearcoupling swap-model publishes a model in
# those cells' partitions only (a proposal's too: applying one is a swap), and its writer is also
# in the operator's own partition, which no other grant has: the monitor learns from it which
# operator swapped, authenticated (live/live_names.h, docs/security.md). It reads the health to
# see it taken and the proposals and audit trail.
operator_rules() {
  local cells partitions=() cell
  IFS=, read -ra cells <<<"$2"
  for cell in "${cells[@]}"; do partitions+=("$CELL_PARTITION_PREFIX$cell"); done
  criteria publish "$MODEL_TOPIC" "${partitions[@]}" "$OPERATOR_PARTITION_PREFIX$1"
  criteria subscribe "$HEALTH_TOPIC" "$LIVE_PARTITION"
  learning_view_rules
}

# The top 32 bits of every client_id of identity ID: from a hash of its name, so reruns agree.
client_prefix() { printf '%s' "$1" | sha256sum | cut -c1-8; }

# make_requester ID RULES_FUNCTION: a member that asks the service, with its client_id_prefix.
make_requester() {
  local prefix; prefix="$(client_prefix "$1")"
  [ "$prefix" != 00000000 ] || fail "$1: its id prefix would be 0; choose another name"
  make_member "$1" "$2" "$prefix"
  echo "$prefix" | write_if_changed "$OUT/$1/client_id_prefix"
}

security_fragment() {
  cat <<XML
<?xml version="1.0" encoding="UTF-8"?>
<!-- Made by deploy/security/make-security.sh: DDS Security for identity $1. Combine it with the
     network configuration: CYCLONEDDS_URI=file:///path/cyclonedds-loopback.xml,file://$OUT/$1/security.xml -->
<CycloneDDS xmlns="https://cdds.io/config">
  <Domain id="any">
    <Security>
      <Authentication>
        <Library path="$LIB_DIR/libdds_security_auth.so" initFunction="init_authentication" finalizeFunction="finalize_authentication"/>
        <IdentityCA>file:$OUT/ca/identity_ca.pem</IdentityCA>
        <IdentityCertificate>file:$OUT/$1/cert.pem</IdentityCertificate>
        <PrivateKey>file:$OUT/$1/key.pem</PrivateKey>
        <CRL>file:$OUT/ca/identity_crl.pem</CRL>
      </Authentication>
      <AccessControl>
        <Library path="$LIB_DIR/libdds_security_ac.so" initFunction="init_access_control" finalizeFunction="finalize_access_control"/>
        <PermissionsCA>file:$OUT/ca/permissions_ca.pem</PermissionsCA>
        <Governance>file:$OUT/governance.p7s</Governance>
        <Permissions>file:$OUT/$1/permissions.p7s</Permissions>
      </AccessControl>
      <Cryptographic>
        <Library path="$LIB_DIR/libdds_security_crypto.so" initFunction="init_crypto" finalizeFunction="finalize_crypto"/>
      </Cryptographic>
    </Security>
  </Domain>
</CycloneDDS>
XML
}

# make_member ID RULES_FUNCTION [ARG]: identity, signed permissions, Cyclone fragment.
make_member() {
  make_identity "$1"
  "${@:2}" | permissions_doc "$1" | write_if_changed "$OUT/$1/permissions.xml"
  sign "$OUT/$1/permissions"
  security_fragment "$1" | write_if_changed "$OUT/$1/security.xml"
}

# ---- revocation -------------------------------------------------------------------------------
CA_DB="$OUT/ca/identity_db"
CRL="$OUT/ca/identity_crl.pem"

# The identity CA's openssl "ca" configuration: a database of revoked certificates (index.txt).
ca_config() {
  cat <<CNF
[ca]
default_ca = identity_ca
[identity_ca]
database = $CA_DB/index.txt
new_certs_dir = $CA_DB
certificate = $OUT/ca/identity_ca.pem
private_key = $OUT/ca/identity_ca_key.pem
default_md = sha256
default_crl_days = $DAYS
unique_subject = no
CNF
}

# Serial numbers (upper-case hex) the database holds as revoked, sorted.
revoked_in_db() { awk -F '\t' '$1 == "R" { print toupper($4) }' "$CA_DB/index.txt" | sort; }
# Serial numbers the CRL lists, sorted.
revoked_in_crl() {
  openssl crl -in "$CRL" -noout -text | sed -n 's/^ *Serial Number: *//p' | tr 'a-f' 'A-F' | sort
}

# revoke ID: puts ID's certificate in the database as revoked, unless it is already.
revoke() {
  local cert="$OUT/$1/cert.pem" serial
  [ -f "$cert" ] || fail "--revoke $1: no certificate $cert to revoke (made by an earlier run)"
  serial="$(openssl x509 -in "$cert" -noout -serial | cut -d= -f2 | tr 'a-f' 'A-F')"
  if revoked_in_db | grep -qx "$serial"; then return; fi
  openssl ca -config <(ca_config) -revoke "$cert" -crl_reason keyCompromise 2>/dev/null \
    || fail "--revoke $1: openssl ca -revoke failed"
}

# The CRL: kept while it verifies against the identity CA, lists exactly the revoked serials and
# is valid for another day; else signed again, valid --days.
make_crl() {
  if [ -f "$CRL" ] && openssl crl -in "$CRL" -CAfile "$OUT/ca/identity_ca.pem" -noout 2>/dev/null \
     && [ "$(date -u -d "$(openssl crl -in "$CRL" -noout -nextupdate | cut -d= -f2)" +%s)" -gt "$(( $(date -u +%s) + 86400 ))" ] \
     && [ "$(revoked_in_crl)" = "$(revoked_in_db)" ]; then
    return
  fi
  openssl ca -config <(ca_config) -gencrl -crldays "$DAYS" -out "$CRL.tmp" 2>/dev/null \
    || fail "openssl ca -gencrl failed"
  chmod 644 "$CRL.tmp"; mv "$CRL.tmp" "$CRL"
}

# ---- the cell ---------------------------------------------------------------------------------
make_ca identity_ca "gearcoupling identity CA" keyCertSign,cRLSign
# The permissions CA signs the documents itself (S/MIME): it needs digitalSignature too.
make_ca permissions_ca "gearcoupling permissions CA" keyCertSign,cRLSign,digitalSignature
write_if_changed "$OUT/governance.xml" <"$(dirname "$0")/governance.xml"
sign "$OUT/governance"
for name in "${SERVICES[@]}"; do make_member "service-$name" service_rules; done
for name in "${CLIENTS[@]}"; do make_requester "client-$name" client_rules; done
for name in "${DASHBOARDS[@]}"; do make_member "dashboard-$name" dashboard_rules; done
for name in ${CONSOLES[@]+"${CONSOLES[@]}"}; do make_requester "console-$name" console_rules; done
for name in ${MONITORS[@]+"${MONITORS[@]}"}; do make_member "monitor-$name" monitor_rules; done
for name in ${CELLS[@]+"${CELLS[@]}"}; do make_member "cell-$name" cell_rules "$name"; done
for name in ${OPERATORS[@]+"${OPERATORS[@]}"}; do
  make_member "operator-$name" operator_rules "$name" "${OPERATOR_CELLS[$name]}"
done
mkdir -p "$CA_DB"
[ -f "$CA_DB/index.txt" ] || : >"$CA_DB/index.txt"
for id in ${REVOKED[@]+"${REVOKED[@]}"}; do revoke "$id"; done
make_crl
rm -f "$OUT/ca/"*.srl.old "$CA_DB/"*.old
echo "DDS Security files for ${#SERVICES[@]} service, ${#CLIENTS[@]} client, ${#DASHBOARDS[@]} dashboard, ${#CONSOLES[@]} console," \
  "${#MONITORS[@]} monitor, ${#CELLS[@]} cell and ${#OPERATORS[@]} operator identities in $OUT;" \
  "$(revoked_in_db | wc -l) revoked"
