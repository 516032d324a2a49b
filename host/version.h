/* The fxrt release version, in one place: fxrt --version prints it (and,
 * when the build embeds it, `git describe` as FXRT_GIT_DESCRIBE). */
#ifndef FXRT_HOST_VERSION_H
#define FXRT_HOST_VERSION_H

#define FXRT_VERSION "0.2.0"

#endif
