/* type_list.h - `gtrace types`: the scene kinds' registered types, or their reference page (type_list.c). */
#ifndef GTRACE_TYPE_LIST_H
#define GTRACE_TYPE_LIST_H

/** The types command: argv[0] is "types", then its options and an optional kind (object, light or camera).
 * Returns the exit status (0, 1 when the types cannot be registered or written, 2 for a usage error). */
int type_list_main(int argc, char **argv);

#endif
