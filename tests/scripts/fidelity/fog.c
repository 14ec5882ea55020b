/* Fog (GL 1.5 §3.10) in its three modes over a receding textured quad each, then lines and
 * points under LINEAR: 64×32, glFrustum(-1, 1, -0.5, 0.5, 1, 30); eye z runs from -2 at the
 * bottom of each quad to -25 at its top. The texture (grey 128, MODULATE) comes before the
 * fog, so a fog applied before texturing would darken the fog colour too. */
glViewport(0, 0, 64, 32);
glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glFrustum(-1, 1, -0.5, 0.5, 1, 30);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glBindTexture(GL_TEXTURE_2D, 1);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){128, 128, 128, 255});
glEnable(GL_TEXTURE_2D);
glEnable(GL_FOG);
glFogfv(GL_FOG_COLOR, (GLfloat[]){0.2, 0.4, 1, 1});
glFogi(GL_FOG_MODE, GL_LINEAR);
glFogf(GL_FOG_START, 1);
glFogf(GL_FOG_END, 20);
/* x_ndc in [-0.5, 0] */
glBegin(GL_QUADS);
glColor3f(1, 0.8, 0.6);
glVertex3f(-1, -1, -2);
glVertex3f(0, -1, -2);
glColor3f(0.6, 1, 0.8);
glVertex3f(0, 12.5, -25);
glVertex3f(-12.5, 12.5, -25);
glEnd();
/* x_ndc in [0, 0.5] */
glFogi(GL_FOG_MODE, GL_EXP);
glFogf(GL_FOG_DENSITY, 0.15);
glBegin(GL_QUADS);
glColor3f(1, 1, 1);
glVertex3f(0, -1, -2);
glVertex3f(1, -1, -2);
glVertex3f(12.5, 12.5, -25);
glVertex3f(0, 12.5, -25);
glEnd();
/* x_ndc in [0.5, 1] */
glFogi(GL_FOG_MODE, GL_EXP2);
glFogf(GL_FOG_DENSITY, 0.08);
glBegin(GL_QUADS);
glColor3f(1, 0.5, 0.2);
glVertex3f(1, -1, -2);
glVertex3f(2, -1, -2);
glVertex3f(25, 12.5, -25);
glVertex3f(12.5, 12.5, -25);
glEnd();
/* x_ndc in [-1, -0.5]: lines and points, LINEAR */
glFogi(GL_FOG_MODE, GL_LINEAR);
glDisable(GL_TEXTURE_2D);
glBegin(GL_LINES);
glColor3f(1, 1, 0);
glVertex3f(-1.8, -0.8, -2);
glVertex3f(-18, 6, -24);
glVertex3f(-1.4, 0.8, -2);
glVertex3f(-14, -8, -24);
glEnd();
glPointSize(3);
glBegin(GL_POINTS);
glColor3f(1, 1, 1);
glVertex3f(-2.4, -1, -3);
glVertex3f(-6.4, 0, -8);
glVertex3f(-12, 3, -15);
glVertex3f(-16, -3, -20);
glEnd();
