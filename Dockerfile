# LadderLab server image: `docker compose up` serves the app on port 8000.
# Three stages: the browser app is built with Node, the Python wheel (with the app inside) is built
# next, and the slim runtime image installs only that wheel and runs as a non-root user.

FROM node:20-bookworm-slim AS frontend
WORKDIR /src/frontend
COPY frontend/package.json frontend/package-lock.json ./
RUN npm ci --no-audit --no-fund
COPY frontend/ ./
COPY shared_schema/ /src/shared_schema/
# vite writes the app into ../backend/ladderlab/server/static
RUN mkdir -p /src/backend/ladderlab/server && npm run build

FROM python:3.11-slim AS wheel
WORKDIR /src
COPY pyproject.toml README.md ./
COPY backend/ backend/
COPY --from=frontend /src/backend/ladderlab/server/static/ backend/ladderlab/server/static/
RUN pip wheel --no-cache-dir --no-deps --wheel-dir /dist .

FROM python:3.11-slim
RUN useradd --create-home --uid 10001 ladderlab
COPY --from=wheel /dist/ /tmp/dist/
RUN pip install --no-cache-dir /tmp/dist/*.whl && rm -rf /tmp/dist
COPY --chown=ladderlab examples/ /app/examples/
ENV LADDERLAB_WORKSPACE=/data/workspace \
    LADDERLAB_EXAMPLES=/app/examples
RUN mkdir -p /data/workspace && chown -R ladderlab /data
USER ladderlab
VOLUME /data
EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=5s --start-period=20s \
    CMD ["python", "-c", "import urllib.request; urllib.request.urlopen('http://127.0.0.1:8000/api/health', timeout=4)"]
CMD ["ladderlab", "serve", "--host", "0.0.0.0", "--port", "8000", "--allow-remote"]
