/** @file
 * The version of pogon: the one place it is written.
 *
 * CMakeLists.txt reads these three lines for project(VERSION), so the CMake package,
 * the shared library's name and pogon.pc carry the same number; the replay writer
 * (src/io/replay_file.c) stores it in every replay header.
 *
 * The rule before 1.0: a change of the numerics (any change of the bits a step
 * produces) bumps the minor version and re-hashes the replay corpus in the same
 * commit; other changes bump the patch version. CHANGELOG.md lists each version.
 */
#ifndef POGON_VERSION_H
#define POGON_VERSION_H

#define POGON_VERSION_MAJOR 0 /**< Major version: 0 until the API and the numerics are stable. */
#define POGON_VERSION_MINOR 3 /**< Minor version: bumped by a change of the numerics or the API. */
#define POGON_VERSION_PATCH 0 /**< Patch version: bumped by a change that keeps every bit and the API. */

/** The version as text, "MAJOR.MINOR.PATCH". */
#define POGON_VERSION_STRING POGON__STR(POGON_VERSION_MAJOR) "." POGON__STR(POGON_VERSION_MINOR) "." POGON__STR(POGON_VERSION_PATCH)
/** @cond INTERNAL */
#define POGON__STR2(x) #x
#define POGON__STR(x) POGON__STR2(x)
/** @endcond */

#endif /* POGON_VERSION_H */
