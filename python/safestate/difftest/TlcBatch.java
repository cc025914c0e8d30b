// Runs TLC on many specs from one JVM (JVM start-up costs ~0.7 s per TLC run).
// Compiled at run time by safestate.difftest.tlc_batch, only when a tla2tools.jar
// is given; never needed by a test.
//
// Protocol: one job per line on stdin, tab-separated:
//     id  dir  module.tla  config.cfg  output-file  metadir
// For each job TLC runs in a fresh class loader (TLC keeps global state in
// static fields), its output goes to output-file, and one line is written to
// stdout: "DONE id exit-code" (or "TIMEOUT id", after which this JVM stops).
import java.io.*;
import java.lang.reflect.*;
import java.net.*;

public final class TlcBatch {
    static final class ExitTrapped extends SecurityException {
        final int status;
        ExitTrapped(int status) { super("exit " + status); this.status = status; }
    }

    public static void main(String[] argv) throws Exception {
        URL jar = new File(argv[0]).toURI().toURL();
        long timeoutMs = Long.parseLong(argv[1]) * 1000L;
        boolean reuse = argv.length > 2 && argv[2].equals("reuse");
        PrintStream ctl = new PrintStream(new FileOutputStream(FileDescriptor.out), true);
        System.setSecurityManager(new SecurityManager() {
            @Override public void checkPermission(java.security.Permission p) { }
            @Override public void checkPermission(java.security.Permission p, Object ctx) { }
            @Override public void checkExit(int status) { throw new ExitTrapped(status); }
        });
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in));
        String line;
        while ((line = in.readLine()) != null) {
            String[] f = line.split("\t");
            if (f.length != 6) { ctl.println("BAD " + line); continue; }
            final int[] code = {-1};
            try (PrintStream out = new PrintStream(new FileOutputStream(f[4]), true)) {
                System.setOut(out);
                System.setErr(out);
                final String[] args = {"-workers", "1", "-metadir", f[5], "-noGenerateSpecTE",
                                       "-config", f[3], new File(f[1], f[2]).getPath()};
                Thread t = new Thread(() -> code[0] = runOne(reuse ? shared(jar) : fresh(jar), f[1], args, out));
                t.setDaemon(true);
                t.start();
                t.join(timeoutMs);
                if (t.isAlive()) {
                    ctl.println("TIMEOUT " + f[0]);
                    Runtime.getRuntime().halt(3);
                }
            }
            ctl.println("DONE " + f[0] + " " + code[0]);
        }
        Runtime.getRuntime().halt(0);
    }

    static URLClassLoader sharedLoader;

    static URLClassLoader fresh(URL jar) {
        return new URLClassLoader(new URL[] {jar}, ClassLoader.getPlatformClassLoader());
    }

    static synchronized URLClassLoader shared(URL jar) {
        if (sharedLoader == null) sharedLoader = fresh(jar);
        return sharedLoader;
    }

    static int runOne(URLClassLoader loader, String dir, String[] args, PrintStream out) {
        try {
            Thread.currentThread().setContextClassLoader(loader);
            Class<?> toolIO = loader.loadClass("util.ToolIO");  // captured System.out on first use
            toolIO.getField("out").set(null, out);
            toolIO.getField("err").set(null, out);
            Class<?> tlcClass = loader.loadClass("tlc2.TLC");
            Object tlc = tlcClass.getConstructor().newInstance();
            Boolean ok = (Boolean) tlcClass.getMethod("handleParameters", String[].class).invoke(tlc, (Object) args);
            if (!ok) return 1;
            Class<?> resolverIf = loader.loadClass("util.FilenameToStream");
            Object resolver = loader.loadClass("util.SimpleFilenameToStream").getConstructor(String.class).newInstance(dir);
            tlcClass.getMethod("setResolver", resolverIf).invoke(tlc, resolver);
            int ec = (Integer) tlcClass.getMethod("process").invoke(tlc);
            // As TLC.main: the process exit status, not the error constant.
            return (Integer) loader.loadClass("tlc2.output.EC$ExitStatus")
                .getMethod("errorConstantToExitStatus", int.class).invoke(null, ec);
        } catch (InvocationTargetException e) {
            Throwable c = e.getCause();
            while (c != null && !(c instanceof ExitTrapped)) c = c.getCause();
            if (c != null) return ((ExitTrapped) c).status;
            e.getCause().printStackTrace(out);
            return 255;
        } catch (ExitTrapped e) {
            return e.status;
        } catch (Throwable e) {
            e.printStackTrace(out);
            return 255;
        }
    }
}
