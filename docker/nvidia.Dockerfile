# Specula on an NVIDIA GPU through EGL_EXT_platform_device (no X server, no display).
# Needs the NVIDIA Container Toolkit; "graphics" makes it mount the driver's EGL libraries.
#   docker build -f docker/nvidia.Dockerfile -t specula:nvidia .
#   docker run --rm --gpus all --user "$(id -u):$(id -g)" -v "$PWD/out:/out" specula:nvidia render --gl egl-device --out /out/frame.png
#   docker run --rm --gpus all -p 8080:8080 -e SPECULA_TOKEN=change-me specula:nvidia serve --bind 0.0.0.0 --gl egl-device
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
# glvnd finds the driver's EGL through this vendor file; the toolkit mounts libEGL_nvidia.so.0 itself.
RUN mkdir -p /usr/share/glvnd/egl_vendor.d \
 && echo '{"file_format_version":"1.0.0","ICD":{"library_path":"libEGL_nvidia.so.0"}}' \
      > /usr/share/glvnd/egl_vendor.d/10_nvidia.json
ENV NVIDIA_VISIBLE_DEVICES=all NVIDIA_DRIVER_CAPABILITIES=graphics,utility,compute
COPY --from=build /build/bin/ /usr/local/bin/
COPY --from=build /src/client/web/ /usr/share/specula/web/
# serve: inside a container the port is only reachable when bound to 0.0.0.0, which needs a token.
EXPOSE 8080
USER nobody
WORKDIR /tmp
ENTRYPOINT ["specula"]
CMD ["--help"]
