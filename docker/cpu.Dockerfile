# Specula on Mesa's software GL (llvmpipe): runs on any x86-64 host, no GPU needed.
#   docker build -f docker/cpu.Dockerfile -t specula:cpu .
#   docker run --rm --user "$(id -u):$(id -g)" -v "$PWD/out:/out" specula:cpu render --scene checker-sphere --out /out/frame.png
#   docker run --rm -p 8080:8080 -e SPECULA_TOKEN=change-me specula:cpu serve --bind 0.0.0.0
#   then open http://localhost:8080/?token=change-me
FROM debian:bookworm-slim AS build
COPY docker/install-deps.sh /src/docker/install-deps.sh
RUN /src/docker/install-deps.sh --build
COPY . /src
RUN cmake -S /src -B /build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSPECULA_BUILD_TESTS=OFF \
      -DSPECULA_WEB_ROOT=/usr/share/specula/web \
 && cmake --build /build

FROM debian:bookworm-slim
COPY docker/install-deps.sh /tmp/install-deps.sh
RUN /tmp/install-deps.sh --runtime && rm -rf /var/lib/apt/lists/* /tmp/install-deps.sh
COPY --from=build /build/bin/ /usr/local/bin/
COPY --from=build /src/client/web/ /usr/share/specula/web/
# serve: inside a container the port is only reachable when bound to 0.0.0.0, which needs a token.
EXPOSE 8080
# llvmpipe uses every core by default; set LP_NUM_THREADS to share a host.
USER nobody
WORKDIR /tmp
ENTRYPOINT ["specula"]
CMD ["--help"]
