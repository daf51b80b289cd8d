#!/usr/bin/env bash
# Runs the build with Debian's Gradle 4.4.1, the only Gradle this project's machines can get:
# the standard wrapper cannot download a distribution here. Installs it when missing (as root).
set -euo pipefail

GRADLE_VERSION=4.4.1
LAUNCHER=/usr/share/gradle/lib/gradle-launcher-$GRADLE_VERSION.jar

missing_packages() {
    local pkgs=()
    [[ -f $LAUNCHER ]] || pkgs+=(gradle)
    # Debian's gradle package pulls only a JRE; compiling needs javac.
    command -v javac >/dev/null 2>&1 || pkgs+=(openjdk-17-jdk-headless)
    echo "${pkgs[@]}"
}

install_hint() {
    echo "gradlew: needs Debian's packages: $1" >&2
    echo "gradlew: install them with: apt-get update && apt-get install -y $1" >&2
}

pkgs=$(missing_packages)
if [[ -n $pkgs ]]; then
    if [[ $(id -u) -ne 0 ]] || ! command -v apt-get >/dev/null 2>&1; then
        install_hint "$pkgs"
        exit 1
    fi
    log=${TMPDIR:-/tmp}/gradlew-install.log
    echo "gradlew: installing $pkgs (about 20 s; log: $log)" >&2
    # Lock timeout: another apt run (or a second gradlew) may hold the dpkg lock.
    if ! { apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q \
            -o DPkg::Lock::Timeout=300 $pkgs; } >"$log" 2>&1; then
        tail -n 20 "$log" >&2
        install_hint "$pkgs"
        exit 1
    fi
    pkgs=$(missing_packages)
    if [[ -n $pkgs ]]; then
        echo "gradlew: installed, but still missing: $pkgs" >&2
        exit 1
    fi
fi

# A CI run is a one-off on a fresh machine: a daemon would only linger after it, and a
# reused daemon keeps the environment of the run that started it.
args=()
if [[ ${CI:-} == true || ${CI:-} == 1 ]]; then
    args+=(--no-daemon)
fi

# Calling the launcher jar directly (as /usr/bin/gradle does, minus its `java -version`
# probe) keeps stderr free of three "openjdk version" lines on every run.
# shellcheck disable=SC2086  # GRADLE_OPTS holds several JVM options
exec java --add-opens java.base/java.lang=ALL-UNNAMED ${JAVA_OPTS:-} ${GRADLE_OPTS:-} \
    -Dorg.gradle.appname=gradlew -classpath "$LAUNCHER" \
    org.gradle.launcher.GradleMain "${args[@]}" "$@"
