/* One smooth quad of four colours over most of the viewport: red, green, blue and white
   corners counter-clockwise from the lower left. Which diagonal a quad is split along shows
   in every pixel's colour. */
glBegin(GL_QUADS);
glColor3f(1, 0, 0);
glVertex2f(-0.9, -0.9);
glColor3f(0, 1, 0);
glVertex2f(0.9, -0.9);
glColor3f(0, 0, 1);
glVertex2f(0.9, 0.9);
glColor3f(1, 1, 1);
glVertex2f(-0.9, 0.9);
glEnd();
