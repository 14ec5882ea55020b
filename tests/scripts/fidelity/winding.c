/* One indexed TRIANGLES mesh under each front face and culled face, smooth (bottom row)
 * and flat (top row), lit on both sides with distinct front and back materials, drawn
 * as given and mirrored (so each cell holds front and back faces), under a perspective
 * whose near plane cuts the mesh, lit from in front and from behind. The emulated path
 * gives llvmpipe some of these draws with each triangle's first two corners swapped and
 * the opposite core front face (pipeline::emulate::draw::Winding). Indices from an
 * element-array buffer, drawn through a display list. 256x128 window, four 64x64 cells
 * per row. */
#include <GL/gl.h>
#include <GL/glext.h>

glClearColor(0.1, 0.1, 0.1, 1);
glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
glEnable(GL_DEPTH_TEST);
glEnable(GL_CULL_FACE);
glEnable(GL_LIGHTING);
glEnable(GL_LIGHT0);
glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){0.3, 0.4, 1, 0});
glEnable(GL_LIGHT1);
glLightfv(GL_LIGHT1, GL_POSITION, (GLfloat[]){-0.2, -0.3, -1, 0});
glLightfv(GL_LIGHT1, GL_DIFFUSE, (GLfloat[]){1, 1, 1, 1});
glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
glEnable(GL_COLOR_MATERIAL);
glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, (GLfloat[]){0.9, 0.2, 0.7, 1});
glVertexPointer(3, GL_FLOAT, 0, (GLfloat[]){-1.0, -1.0, -1.2159, -0.5, -1.0, -1.1513, 0.0, -1.0, -1.058, 0.5, -1.0, -0.9013, 1.0, -1.0, -0.7159, -1.0, -0.5, -1.4248, -0.5, -0.5, -0.9903, 0.0, -0.5, -0.703, 0.5, -0.5, -0.7403, 1.0, -0.5, -0.9248, -1.0, 0.0, -1.5148, -0.5, 0.0, -0.9209, 0.0, 0.0, -0.55, 0.5, 0.0, -0.6709, 1.0, 0.0, -1.0148, -1.0, 0.5, -1.4248, -0.5, 0.5, -0.9903, 0.0, 0.5, -0.703, 0.5, 0.5, -0.7403, 1.0, 0.5, -0.9248, -1.0, 1.0, -1.2159, -0.5, 1.0, -1.1513, 0.0, 1.0, -1.058, 0.5, 1.0, -0.9013, 1.0, 1.0, -0.7159});
glNormalPointer(GL_FLOAT, 0, (GLfloat[]){0.2822, -0.1881, 0.9407, 0.1455, -0.194, 0.9701, -0.0, -0.1961, 0.9806, -0.1455, -0.194, 0.9701, -0.2822, -0.1881, 0.9407, 0.286, -0.0953, 0.9535, 0.1476, -0.0984, 0.9841, -0.0, -0.0995, 0.995, -0.1476, -0.0984, 0.9841, -0.286, -0.0953, 0.9535, 0.2873, 0.0, 0.9578, 0.1483, 0.0, 0.9889, -0.0, 0.0, 1.0, -0.1483, 0.0, 0.9889, -0.2873, 0.0, 0.9578, 0.286, 0.0953, 0.9535, 0.1476, 0.0984, 0.9841, -0.0, 0.0995, 0.995, -0.1476, 0.0984, 0.9841, -0.286, 0.0953, 0.9535, 0.2822, 0.1881, 0.9407, 0.1455, 0.194, 0.9701, -0.0, 0.1961, 0.9806, -0.1455, 0.194, 0.9701, -0.2822, 0.1881, 0.9407});
glColorPointer(3, GL_FLOAT, 0, (GLfloat[]){0.2, 0.6, 0.9, 0.4, 0.6, 0.825, 0.6, 0.6, 0.75, 0.8, 0.6, 0.675, 1.0, 0.6, 0.6, 0.2, 0.7, 0.825, 0.4, 0.7, 0.75, 0.6, 0.7, 0.675, 0.8, 0.7, 0.6, 1.0, 0.7, 0.525, 0.2, 0.8, 0.75, 0.4, 0.8, 0.675, 0.6, 0.8, 0.6, 0.8, 0.8, 0.525, 1.0, 0.8, 0.45, 0.2, 0.9, 0.675, 0.4, 0.9, 0.6, 0.6, 0.9, 0.525, 0.8, 0.9, 0.45, 1.0, 0.9, 0.375, 0.2, 1.0, 0.6, 0.4, 1.0, 0.525, 0.6, 1.0, 0.45, 0.8, 1.0, 0.375, 1.0, 1.0, 0.3});
glEnableClientState(GL_VERTEX_ARRAY);
glEnableClientState(GL_NORMAL_ARRAY);
glEnableClientState(GL_COLOR_ARRAY);
glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 1);
glBufferData(GL_ELEMENT_ARRAY_BUFFER, 192, (GLushort[]){0, 1, 5, 1, 6, 5, 1, 2, 6, 2, 7, 6, 2, 3, 7, 3, 8, 7, 3, 4, 8, 4, 9, 8, 5, 6, 10, 6, 11, 10, 6, 7, 11, 7, 12, 11, 7, 8, 12, 8, 13, 12, 8, 9, 13, 9, 14, 13, 10, 11, 15, 11, 16, 15, 11, 12, 16, 12, 17, 16, 12, 13, 17, 13, 18, 17, 13, 14, 18, 14, 19, 18, 15, 16, 20, 16, 21, 20, 16, 17, 21, 17, 22, 21, 17, 18, 22, 18, 23, 22, 18, 19, 23, 19, 24, 23}, GL_STATIC_DRAW);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glFrustum(-0.3, 0.3, -0.3, 0.3, 0.3, 10);
glMatrixMode(GL_MODELVIEW);
/* Both copies, as given and mirrored. */
glNewList(1, GL_COMPILE);
glLoadIdentity();
glTranslatef(0.32, 0, 0.15);
glScalef(0.55, 0.55, 1);
glDrawElements(GL_TRIANGLES, 96, GL_UNSIGNED_SHORT, (const void *)0);
glLoadIdentity();
glTranslatef(-0.32, 0, 0.15);
glScalef(-0.55, 0.55, 1);
glDrawElements(GL_TRIANGLES, 96, GL_UNSIGNED_SHORT, (const void *)0);
glEndList();
glShadeModel(GL_SMOOTH);
/* smooth, front face CCW, cull BACK */
glViewport(0, 0, 64, 64);
glFrontFace(GL_CCW);
glCullFace(GL_BACK);
glCallList(1);
/* smooth, front face CW, cull FRONT */
glViewport(64, 0, 64, 64);
glFrontFace(GL_CW);
glCullFace(GL_FRONT);
glCallList(1);
/* smooth, front face CCW, cull FRONT */
glViewport(128, 0, 64, 64);
glFrontFace(GL_CCW);
glCullFace(GL_FRONT);
glCallList(1);
/* smooth, front face CW, cull BACK */
glViewport(192, 0, 64, 64);
glFrontFace(GL_CW);
glCullFace(GL_BACK);
glCallList(1);
glShadeModel(GL_FLAT);
/* flat, front face CCW, cull BACK */
glViewport(0, 64, 64, 64);
glFrontFace(GL_CCW);
glCullFace(GL_BACK);
glCallList(1);
/* flat, front face CW, cull FRONT */
glViewport(64, 64, 64, 64);
glFrontFace(GL_CW);
glCullFace(GL_FRONT);
glCallList(1);
/* flat, front face CCW, cull FRONT */
glViewport(128, 64, 64, 64);
glFrontFace(GL_CCW);
glCullFace(GL_FRONT);
glCallList(1);
/* flat, front face CW, cull BACK */
glViewport(192, 64, 64, 64);
glFrontFace(GL_CW);
glCullFace(GL_BACK);
glCallList(1);
