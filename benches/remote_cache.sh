#!/bin/bash
# docs/performance.md, "The team's cache on a server". Usage:
#   KILN=target/release/kiln SCALE=<the scale bench's binary> NGINX=/usr/sbin/nginx \
#     SIZE=10000 ROUNDS=5 benches/remote_cache.sh
# (the scale binary: `cargo bench --bench scale --no-run`, target/release/deps/scale-*; nginx:
# Debian's package, or its binary with its libraries in LD_LIBRARY_PATH).
# The remote cache: nginx (Debian's, with its libraries) on loopback; a whole build
# cold and publishing, another "machine" against the warm server, a plain cold build; then 16
# shards at once (1 thread each) cold and publishing, merged, and 16 again on fresh folders
# against the warm server. Each line: what, seconds, modules compiled.
set -u
B=$(cd "$(dirname "$0")" && pwd); K=${KILN:-$B/kiln}; SCALE=${SCALE:-$B/scale-new}; NGINX=${NGINX:-$B/nginx/nginx}; W=/tmp/rc; P=$W/project; URL=http://127.0.0.1:18080/kiln
rm -rf $W; mkdir -p $W
$SCALE generate ${SIZE:-10000} $P > /dev/null
cat > $W/nginx.conf <<CONF
daemon off; master_process on; worker_processes 8; user root; pid $W/nginx.pid; error_log $W/error.log;
events { worker_connections 4096; }
http { access_log off; client_body_temp_path $W/body; proxy_temp_path $W/proxy; fastcgi_temp_path $W/fastcgi; uwsgi_temp_path $W/uwsgi; scgi_temp_path $W/scgi; client_body_buffer_size 1m;
  server { listen 127.0.0.1:18080; root $W/root;
    location / { dav_methods PUT; create_full_put_path on; client_max_body_size 0; log_not_found off; } } }
CONF
LD_LIBRARY_PATH=$(dirname $NGINX) $NGINX -p $W -c $W/nginx.conf -e $W/error.log &
sleep 1
t() { local s=$(date +%s%N); "$@" > $W/last.log 2>&1; local e=$(date +%s%N); echo "$(( (e - s) / 1000000 ))ms $(grep -o '([0-9]* compiled' $W/last.log | tr -d '(' | awk '{s+=$1} END {print s+0}')"; }
for r in $(seq 1 ${ROUNDS:-5}); do
  rm -rf $W/root $W/o $W/c; mkdir -p $W/root/kiln
  echo "round $r plain-cold $(t $K build $P --output $W/o/plain)"
  echo "round $r whole-cold-publish $(t $K build $P --output $W/o/a --cache-dir $W/c/a --remote-cache $URL)"
  echo "round $r whole-warm-remote $(t $K build $P --output $W/o/b --cache-dir $W/c/b --remote-cache $URL)"
  diff -rq -x .cache $W/o/a $W/o/b > /dev/null && diff -rq -x .cache $W/o/a $W/o/plain > /dev/null || echo "round $r DIFFERENT"
  echo "round $r server-bytes $(du -sb $W/root | cut -f1)"
  rm -rf $W/root; mkdir -p $W/root/kiln
  shards() { for i in $(seq 1 16); do $K build $P --threads 1 --shard $i/16 --output $W/o/$1-$i --cache-dir $W/c/$1-$i --remote-cache $URL > $W/o/$1-$i.log 2>&1 & done; wait; $K merge $W/o/$1 $(for i in $(seq 1 16); do echo $W/o/$1-$i; done) > /dev/null 2>&1; cat $W/o/$1-*.log > $W/last.log; }
  echo "round $r shards16-cold-publish $(t shards s1)"
  echo "round $r shards16-warm-remote $(t shards s2)"
  diff -rq -x .cache $W/o/s1 $W/o/s2 > /dev/null && diff -rq -x .cache $W/o/s1 $W/o/plain > /dev/null || echo "round $r SHARDS DIFFERENT"
done
kill %1 2>/dev/null
