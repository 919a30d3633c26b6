/* datadir.h: where an installed gallop finds its data (conductors.csv, aero/, scenes/). */
#ifndef GALLOP_BASE_DATADIR_H
#define GALLOP_BASE_DATADIR_H

#ifdef __cplusplus
extern "C" {
#endif

/* The installed data directory baked in at build time ($(PREFIX)/share/gallop for `make install`),
 * or "" (a build tree). The scene reader looks for conductors.csv in $GALLOP_DATA, then here, then
 * in ./data, then beside the scene's directory. */
const char *gal_datadir_installed(void);

#ifdef __cplusplus
}
#endif

#endif
